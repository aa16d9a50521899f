// The nonmonotone line search (Nonlinear solver/Line search memory), on the
// potential Phi = (x^2 + 100 y^2)/2, r = (x, 100 y), root 0, with scripted
// directions (the stress-velocity tangent is not the derivative of r, so a
// direction may lower Phi while |r| rises, as while a plastic zone forms):
// - iteration 1, from (1, 0.049) with |r| = 5: dv = (0, -0.049), to (1, 0)
//   with |r| = 1;
// - iteration 2: dv = (-0.6, -0.04). At the full step Phi still falls
//   (g(1) = -0.08 < 0) but |r| = 4.02 > 1.
// With memory 3 the reference is max(5, 1) = 5 and the full step is taken.
// With memory 1 (monotone) it must not be: the search halves down to
// alpha = 1/16, the first trial with |r| < 1.
// - iteration 3: the exact direction -x, to the root with either memory.
#include <deal.II/base/mpi.h>

#include <formsolve/newton/newton_solver.h>

#include "check.h"
#include "toy_problem.h"

#include <cmath>

using namespace formsolve;

namespace
{
  class ScriptedQuadratic : public test::ToyProblem
  {
  public:
    explicit ScriptedQuadratic(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      return compute(v);
    }
    double assemble_residual(const VectorType &v) override
    {
      return compute(v);
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      ++solves;
      if (solves == 1)
        {
          dv[0] = 0;
          dv[1] = -0.049;
        }
      else if (solves == 2)
        {
          dv[0] = -0.6;
          dv[1] = -0.04;
        }
      else
        {
          dv[0] = -x[0];
          dv[1] = -x[1];
        }
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }

    double x[2] = {0, 0};

  private:
    double compute(const VectorType &v)
    {
      x[0] = v[0];
      x[1] = v[1];
      r[0] = x[0];
      r[1] = 100 * x[1];
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    unsigned int solves = 0;
    VectorType   r;
  };

  // Iterations 1 and 2 (and 3) with the given memory; returns the report.
  solver::NewtonReport run(const unsigned int memory,
                           const unsigned int iterations,
                           double            &x,
                           double            &y)
  {
    dealii::IndexSet two(2);
    two.add_range(0, 2);
    parameters::NonlinearSolver p;
    p.picard_fallback    = false;
    p.line_search_memory = memory;
    p.max_iterations     = iterations;
    ScriptedQuadratic            system(two);
    test::ToyProblem::VectorType v(two, MPI_COMM_WORLD);
    v[0] = 1;
    v[1] = 0.049;
    v.compress(dealii::VectorOperation::insert);
    const dealii::ConditionalOStream quiet(std::cout, false);
    const auto report = system.solve_from(solver::NewtonSolver(p, quiet), v);
    x                 = v[0];
    y                 = v[1];
    std::cout << "memory " << memory << ", " << report.iterations
              << " iterations: (" << x << ", " << y
              << "), |r| = " << report.residual << std::endl;
    return report;
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double                                   x = 0, y = 0;

  auto report = run(3, 2, x, y);
  test::close("memory 3: full step taken in iteration 2 (x)", x, 0.4, 1e-12);
  test::close("memory 3: full step taken in iteration 2 (y)", y, -0.04, 1e-12);
  test::close("memory 3: |r| rose to 4.02 (below the reference 5)",
              report.residual,
              std::hypot(0.4, 4.),
              1e-12);

  report = run(1, 2, x, y);
  test::close("memory 1: |r| fell in iteration 2", report.residual < 1, 1, 0);
  test::close("memory 1: alpha = 1/16 in iteration 2 (x)",
              x,
              1 - 0.6 / 16,
              1e-12);

  for (const unsigned int memory : {1u, 3u})
    {
      report = run(memory, 10, x, y);
      test::close("converged", report.converged, 1, 0);
      test::close("at the root", std::hypot(x, y), 0, 1e-12);
    }
  return test::result();
}
