// Two line-search situations of the forming solves, on scalar systems.
// 1. A contact that closes within the step (the blank holder meeting more
//    of the flange): r(x) = x - 1 + 50 max(x - 0.9, 0), tangent 1 (the
//    closing pair is not yet in the linearisation), from x = 0. The full
//    step overshoots (r = 5), regula falsi proposes 1/6, where r still
//    falls steeply (g = -0.83 g0). That trial must not end the search: the
//    accepted iterate has |g| <= |g0|/2, i.e. |r| <= 1/2 here (before, the
//    first descending trial was taken and each iteration crept by 1/6).
// 2. A direction that lowers the potential but not |r| (the
//    stress-velocity tangent is not the derivative of r): r(x) = -1 - x,
//    whose ordinary tangent is +1 (positive, as a secant) and whose exact
//    one (assemble_exact) is -1. From x = 0 every trial along dv = -r = 1
//    has g < 0 and a larger |r|. After that stalled iteration the iterate
//    must not have moved (before, the shortest trial was taken although its
//    |r| was larger), and the next direction comes from the exact tangent,
//    which reaches the root x = -1.
#include <deal.II/base/mpi.h>

#include <formsolve/newton/newton_solver.h>

#include "check.h"
#include "toy_problem.h"

#include <algorithm>
#include <cmath>

using namespace formsolve;

namespace
{
  class ScalarSystem : public test::ToyProblem
  {
  public:
    explicit ScalarSystem(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      exact = false;
      return compute(v);
    }
    double assemble_exact(const VectorType &v) override
    {
      ++exact_assemblies;
      const double norm = compute(v);
      exact             = true;
      return norm;
    }
    double assemble_residual(const VectorType &v) override
    {
      return compute(v);
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }

    unsigned int exact_assemblies = 0;

  protected:
    virtual double residual(const double x) const = 0;
    double         compute(const VectorType &v)
    {
      x    = v[0];
      r[0] = residual(x);
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    double     x     = 0;
    bool       exact = false;
    VectorType r;
  };

  class ClosingContact : public ScalarSystem
  {
  public:
    using ScalarSystem::ScalarSystem;
    unsigned int linear_solve(VectorType &dv) override
    {
      dv[0] = -r[0]; // the closing pair is not in the tangent
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }

  private:
    double residual(const double x) const override
    {
      return x - 1 + 50 * std::max(x - 0.9, 0.);
    }
  };

  class NoDescent : public ScalarSystem
  {
  public:
    using ScalarSystem::ScalarSystem;
    unsigned int linear_solve(VectorType &dv) override
    {
      dv[0] = exact ? r[0] : -r[0];
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }

  private:
    double residual(const double x) const override { return -1 - x; }
  };
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::IndexSet                         one(1);
  one.add_range(0, 1);
  parameters::NonlinearSolver p;
  p.picard_fallback = false;
  const dealii::ConditionalOStream quiet(std::cout, false);

  {
    p.max_iterations = 1;
    ClosingContact               system(one);
    test::ToyProblem::VectorType v(one, MPI_COMM_WORLD);
    const auto report = system.solve_from(solver::NewtonSolver(p, quiet), v);
    std::cout << "closing contact: x = " << v[0]
              << ", |r| = " << report.residual << std::endl;
    test::close("closing contact: |g| at most half of |g0|",
                report.residual <= 0.5,
                1,
                0);
    test::close("closing contact: short of the kink", v[0] < 0.9, 1, 0);
  }
  {
    p.max_iterations = 1;
    NoDescent                    system(one);
    test::ToyProblem::VectorType v(one, MPI_COMM_WORLD);
    auto report = system.solve_from(solver::NewtonSolver(p, quiet), v);
    std::cout << "no descent, one iteration: x = " << v[0]
              << ", |r| = " << report.residual << std::endl;
    test::close("no descent: the iterate stays", v[0], 0, 0);
    test::close("no descent: |r| unchanged", report.residual, 1, 0);
    test::close("no descent: not converged", report.converged, 0, 0);
    test::close("no descent: exact tangent assembled",
                system.exact_assemblies,
                1,
                0);

    p.max_iterations = 10;
    NoDescent                    again(one);
    test::ToyProblem::VectorType w(one, MPI_COMM_WORLD);
    report = again.solve_from(solver::NewtonSolver(p, quiet), w);
    std::cout << "no descent: " << report.iterations
              << " iterations, x = " << w[0] << std::endl;
    test::close("no descent: converged with the exact direction",
                report.converged,
                1,
                0);
    test::close("no descent: at the root", w[0], -1, 1e-12);
  }
  return test::result();
}
