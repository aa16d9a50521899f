// Inexact Newton (Nonlinear solver/Forcing): an inexact direction that does
// not descend must not be taken. On r(x) = x - 1 from x = 0 the "linear
// solver" returns, whenever it may stop early (tolerance > 0), the ascent
// direction dv = +r (g0 = dv . r > 0), and the exact dv = -r at tolerance 0.
// Before the guard the full step was taken whenever g0 >= 0, so |r| doubled
// at every iteration; now the iterate stays, the next solve is tight and the
// root is reached in the second iteration; |r| at the iterates never grows.
#include <deal.II/base/mpi.h>

#include <formsolve/newton/newton_solver.h>

#include "check.h"
#include "toy_problem.h"

#include <algorithm>
#include <vector>

using namespace formsolve;

namespace
{
  class InexactLine : public test::ToyProblem
  {
  public:
    explicit InexactLine(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      r[0] = v[0] - 1;
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    // |r| at the accepted iterates (line-search trials are not iterates).
    void   accept_step() override { largest = std::max(largest, r.l2_norm()); }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }
    void set_linear_tolerance(const double t) override { tolerance = t; }
    unsigned int linear_solve(VectorType &dv) override
    {
      tolerances.push_back(tolerance);
      dv[0] = tolerance > 0 ? r[0] : -r[0];
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }

    double              tolerance = 0, largest = 0;
    std::vector<double> tolerances;

  private:
    VectorType r;
  };
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::IndexSet                         one(1);
  one.add_range(0, 1);
  parameters::NonlinearSolver p;
  p.picard_fallback = false;
  p.forcing         = 1;
  p.max_iterations  = 10;
  const dealii::ConditionalOStream quiet(std::cout, false);

  InexactLine                  system(one);
  test::ToyProblem::VectorType v(one, MPI_COMM_WORLD);
  const auto report = system.solve_from(solver::NewtonSolver(p, quiet), v);
  std::cout << report.iterations << " iterations, x = " << v[0]
            << ", largest |r| " << system.largest << ", tolerances";
  for (const double t : system.tolerances)
    std::cout << ' ' << t;
  std::cout << std::endl;
  test::close("the first solve may stop early", system.tolerances[0], 0.1, 0);
  test::close("the second solve is tight", system.tolerances.at(1), 0, 0);
  test::close("converged", report.converged, 1, 0);
  test::close("at the root", v[0], 1, 1e-12);
  test::close("|r| never grew", system.largest, 1, 1e-12);
  return test::result();
}
