// The Newton line search on systems built to trap it.
// 1. Along the solver's direction the directional derivative
//    g(alpha) = dv.r(v + alpha dv) is still negative at the full step while
//    |r| has doubled (2.06 from 1). The step must not be accepted there: the
//    accepted iterate has a smaller |r| than the start, and the
//    residual-only trials assemble no matrix. (The search for a longer
//    step within the bracket: newton_stall_bracket.)
// 2. An extra unknown (as the blank holder's velocity under force control)
//    whose equation alone is off at the start, with the body in equilibrium:
//    the exact Newton step must be taken whole (the line search measures the
//    body and the extra residual together, not |r| of the body alone).
// 3. Convergence on the error left (Correction measure = contraction,
//    doc/theory.md eq. 10a) on r(x) = x + x^3 - 10 (root 2), where only the
//    correction criterion decides: from several starts and tolerances the
//    returned x is within the tolerance of the root (the estimate bounds
//    the error), never after more iterations than with the last correction,
//    and after fewer in at least one case.
#include <deal.II/base/mpi.h>

#include <formsolve/newton/newton_solver.h>

#include "check.h"
#include "toy_problem.h"

#include <cmath>
#include <sstream>

using namespace formsolve;

namespace
{
  // r(x, y) = (x - 1, y + 8 x^2); the "tangent" returns dv = -r/2 in x and
  // nothing in y: a descent direction for the first equation only.
  class TrapSystem : public test::ToyProblem
  {
  public:
    explicit TrapSystem(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      ++assemblies;
      return compute(v);
    }
    double assemble_residual(const VectorType &v) override
    {
      ++residual_assemblies;
      return compute(v);
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      dv    = 0;
      dv[0] = -0.5 * r[0];
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }

    unsigned int assemblies = 0, residual_assemblies = 0;

  private:
    double compute(const VectorType &v)
    {
      const double x = v[0], y = v[1];
      r[0] = x - 1;
      r[1] = y + 8 * x * x;
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    VectorType r;
  };

  // Body r(x, w) = x - w, extra rho(x, w) = w - 1, from (0, 0): the body is
  // in equilibrium, rho = -1; Newton: dw = 1, dx = 1, exact at alpha = 1.
  class ExtraUnknownSystem : public test::ToyProblem
  {
  public:
    explicit ExtraUnknownSystem(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      x    = v[0];
      r[0] = x - w_trial;
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv + dw * rho();
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      dw    = -rho();
      dv    = 0;
      dv[0] = -r[0] + dw;
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }
    void set_step_length(const double alpha) override
    {
      w_trial = w + alpha * dw;
    }
    void   accept_step() override { w = w_trial; }
    double extra_residual() const override { return std::abs(rho()); }
    double extra_residual_norm() const override { return std::abs(rho()); }

    double w = 0, w_trial = 0;

  private:
    double     rho() const { return w_trial - 1; }
    double     x = 0, dw = 0;
    VectorType r;
  };
  // r(x) = x + x^3 - 10 with its exact Newton step.
  class CubicSystem : public test::ToyProblem
  {
  public:
    explicit CubicSystem(const dealii::IndexSet &owned)
        : r(owned, MPI_COMM_WORLD)
    {}
    double assemble(const VectorType &v, const bool /*newton*/) override
    {
      x    = v[0];
      r[0] = x + x * x * x - 10;
      r.compress(dealii::VectorOperation::insert);
      return r.l2_norm();
    }
    double force_scale() const override { return 1; }
    double directional_derivative(const VectorType &dv) const override
    {
      return r * dv;
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      dv[0] = -r[0] / (1 + 3 * x * x);
      dv.compress(dealii::VectorOperation::insert);
      return 1;
    }

  private:
    double     x = 0;
    VectorType r;
  };
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::IndexSet                         owned(2);
  owned.add_range(0, 2);
  TrapSystem                   system(owned);
  test::ToyProblem::VectorType v(owned, MPI_COMM_WORLD);

  parameters::NonlinearSolver p;
  p.max_iterations  = 1;
  p.picard_fallback = false;
  solver::NewtonSolver newton(p, dealii::ConditionalOStream(std::cout, false));
  const auto           report = system.solve_from(newton, v);
  std::cout << "accepted x = " << v[0] << ", |r| = " << report.residual
            << std::endl;
  test::close("|r| decreased from 1", report.residual < 1, 1, 0);
  test::close("the full step (|r| = 2.06) was not accepted", v[0] < 0.5, 1, 0);
  // The start, the full step (rejected), the accepted trial. The half step
  // still descends steeply (g = 0.75 g0), so the search zooms into [1/2, 1]
  // and, with every longer trial above |r| = 1, ends at the longest
  // descending one: all trials after the full step assembled their residual
  // only.
  test::close("matrix assemblies", system.assemblies, 3, 0);
  test::close("residual-only assemblies",
              system.residual_assemblies,
              p.max_line_search_steps,
              0);

  dealii::IndexSet one(1);
  one.add_range(0, 1);
  ExtraUnknownSystem           extra(one);
  test::ToyProblem::VectorType x(one, MPI_COMM_WORLD);
  extra.solve_from(newton, x);
  std::cout << "extra unknown: x = " << x[0] << ", w = " << extra.w
            << std::endl;
  test::close("extra unknown: the whole Newton step", extra.w, 1, 1e-12);
  test::close("extra unknown: body follows", x[0], 1, 1e-12);

  unsigned int fewer = 0;
  for (const double start : {1., 5., -3.})
    for (const double tol : {1e-3, 1e-6, 1e-9})
      {
        unsigned int iterations[2];
        double       error[2];
        for (const auto measure : {parameters::CorrectionMeasure::last,
                                   parameters::CorrectionMeasure::contraction})
          {
            parameters::NonlinearSolver q;
            q.residual_tolerance   = 1e10; // the correction decides
            q.correction_tolerance = tol;
            q.correction_measure   = measure;
            q.picard_fallback      = false;
            CubicSystem                  cubic(one);
            test::ToyProblem::VectorType c(one, MPI_COMM_WORLD);
            c[0] = start;
            c.compress(dealii::VectorOperation::insert);
            const auto report =
              cubic.solve_from(solver::NewtonSolver(
                                 q,
                                 dealii::ConditionalOStream(std::cout, false)),
                               c);
            const unsigned int k =
              measure == parameters::CorrectionMeasure::contraction;
            iterations[k] = report.converged ? report.iterations : 1000;
            error[k]      = std::abs(c[0] - 2) / 2;
          }
        std::ostringstream name;
        name << "cubic from " << start << ", tol " << tol << ": ";
        const std::string what = name.str();
        std::cout << what << iterations[0] << " iterations (last correction), "
                  << iterations[1] << " (contraction)" << std::endl;
        test::close(what + "error within the tolerance", error[1] <= tol, 1, 0);
        test::close(what + "no more iterations",
                    iterations[1] <= iterations[0],
                    1,
                    0);
        fewer += iterations[1] < iterations[0];
      }
  test::close("contraction saved an iteration somewhere", fewer > 0, 1, 0);
  return test::result();
}
