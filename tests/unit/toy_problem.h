// Small test systems for Newton's method, written as vectors in and norms
// out (assemble, solve, directional derivative), turned into a
// solver::NonlinearProblem: the adapter owns the iterate's direction and
// trial and calls the hooks as the problem's evaluate/solve/accept.
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/newton/newton_solver.h>

namespace test
{
  using formsolve::solver::Accepted;
  using formsolve::solver::Direction;
  using formsolve::solver::Evaluation;
  using formsolve::solver::Linearisation;

  class ToyProblem : public formsolve::solver::NonlinearProblem
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// Residual (and tangent: Newton or secant) at @p v; returns |r|.
    virtual double assemble(const VectorType &v, const bool newton) = 0;
    /// The residual only (line-search trials).
    virtual double assemble_residual(const VectorType &v)
    {
      return assemble(v, true);
    }
    /// With the exact derivative of the residual as the tangent.
    virtual double assemble_exact(const VectorType &v)
    {
      return assemble(v, true);
    }
    virtual double       force_scale() const { return 1; }
    virtual double       directional_derivative(const VectorType &dv) const = 0;
    virtual unsigned int linear_solve(VectorType &dv)                       = 0;
    virtual void         set_linear_tolerance(const double) {}
    /// Extra unknowns follow the trial at step length @p alpha.
    virtual void   set_step_length(const double) {}
    virtual void   accept_step() {}
    virtual double extra_residual() const { return 0; }
    virtual double extra_residual_norm() const { return 0; }
    virtual double extra_correction() const { return 0; }
    virtual bool   active_set_changed() { return false; }
    /// Equations that change with the accepted iterate: the new |r|, or -1.
    virtual double update_equations() { return -1; }
    /// Near convergence: the new |r|, or -1.
    virtual double tighten_equations() { return -1; }

    /// Newton's solve from @p v (the iterate, updated in place).
    formsolve::solver::NewtonReport
    solve_from(const formsolve::solver::NewtonSolver &newton,
               VectorType                            &v,
               const double                           check_residual = 0)
    {
      x = &v;
      direction.reinit(v);
      trial.reinit(v);
      return newton.solve(*this, check_residual);
    }

    Evaluation evaluate(const double        alpha,
                        const Linearisation kind,
                        const bool          tangent_now) override
    {
      trial = *x;
      trial.add(alpha, direction);
      set_step_length(alpha);
      const double r = kind == Linearisation::exact ? assemble_exact(trial)
                       : tangent_now
                         ? assemble(trial, kind == Linearisation::newton)
                         : assemble_residual(trial);
      last           = norms(r);
      last.slope     = directional_derivative(direction);
      return last;
    }

    Direction solve(const double tolerance) override
    {
      set_linear_tolerance(tolerance);
      Direction d;
      direction           = 0;
      d.linear_iterations = linear_solve(direction);
      d.norm              = direction.l2_norm();
      VectorType full(*x);
      full.add(1., direction);
      d.full_step_norm = full.l2_norm();
      d.extra_relative = extra_correction();
      d.slope          = directional_derivative(direction);
      return d;
    }

    Accepted accept() override
    {
      *x = trial;
      accept_step();
      Accepted     a;
      const double r       = update_equations();
      a.evaluation         = norms(r >= 0 ? r : last.residual);
      a.active_set_changed = active_set_changed();
      a.norm               = x->l2_norm();
      a.extra_relative     = extra_correction();
      return a;
    }

    bool tighten(Evaluation &e) override
    {
      const double r = tighten_equations();
      if (r < 0)
        return false;
      e = norms(r);
      return true;
    }

  private:
    Evaluation norms(const double r) const
    {
      Evaluation e;
      e.residual       = r;
      e.extra          = extra_residual_norm();
      e.extra_relative = extra_residual();
      e.scale          = force_scale();
      return e;
    }

    VectorType *x = nullptr;
    VectorType  direction, trial;
    Evaluation  last;
  };
} // namespace test
