// The Newton line search on a system built to trap it: along the solver's
// direction the directional derivative g(alpha) = dv.r(v + alpha dv) is still
// negative at the full step while |r| has doubled (2.06 from 1). The step must
// not be accepted there: the accepted iterate has a smaller |r| than the start,
// and the residual-only trials assemble no matrix.
#include <deal.II/base/mpi.h>

#include <formsolve/solver/newton_solver.h>

#include "check.h"

using namespace formsolve;

namespace
{
  // r(x, y) = (x - 1, y + 8 x^2); the "tangent" returns dv = -r/2 in x and
  // nothing in y: a descent direction for the first equation only.
  class TrapSystem : public solver::NonlinearSystem
  {
  public:
    explicit TrapSystem(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      ++assemblies;
      return evaluate(v);
    }
    double assemble_residual(const VectorType &v) override
    {
      ++residual_assemblies;
      return evaluate(v);
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }
    unsigned int solve(VectorType &dv) override
    {
      dv    = 0;
      dv[0] = -0.5 * r[0];
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }
    bool contact_set_changed() override { return false; }

    unsigned int assemblies = 0, residual_assemblies = 0;

  private:
    double evaluate(const VectorType &v)
    {
      const double x = v[0], y = v[1];
      r[0] = x - 1;
      r[1] = y + 8 * x * x;
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    VectorType r;
  };
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::IndexSet                         owned(2);
  owned.add_range(0, 2);
  TrapSystem                          system(owned);
  solver::NonlinearSystem::VectorType v(owned, MPI_COMM_WORLD);

  parameters::NonlinearSolver p;
  p.max_iterations  = 1;
  p.picard_fallback = false;
  solver::NewtonSolver newton(p, dealii::ConditionalOStream(std::cout, false));
  const auto           report = newton.solve(system, v);
  std::cout << "accepted x = " << v[0] << ", |r| = " << report.residual
            << std::endl;
  test::close("|r| decreased from 1", report.residual < 1, 1, 0);
  test::close("the full step (|r| = 2.06) was not accepted", v[0] < 0.5, 1, 0);
  // The start, the full step (rejected), the accepted half step: the trial at
  // the half step assembled its residual only.
  test::close("matrix assemblies", system.assemblies, 3, 0);
  test::close("residual-only assemblies", system.residual_assemblies, 1, 0);
  return test::result();
}
