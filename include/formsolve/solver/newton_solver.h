// Newton-Raphson with line search and a fallback to direct (Picard) iteration.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/parameters/parameters.h>

#include <string>

namespace formsolve
{
  namespace solver
  {
    /// What the Newton solver needs from a discrete problem. The problem owns
    /// its matrix and residual; the solver only steers.
    class NonlinearSystem
    {
    public:
      using VectorType           = dealii::TrilinosWrappers::MPI::Vector;
      virtual ~NonlinearSystem() = default;

      /// Evaluate contact and assemble the residual (and the tangent: Newton
      /// or secant) at @p v. Returns |r|.
      virtual double assemble(const VectorType &v, const bool newton) = 0;
      /// As assemble(), the residual only (line-search trials); the matrix
      /// keeps what the last assemble() put there.
      virtual double assemble_residual(const VectorType &v)
      {
        return assemble(v, true);
      }
      /// As assemble(): the residual now, the tangent deferred until the
      /// system needs it (solve(), a penalty estimate), for a full step
      /// expected to be the last iterate; if another trial is assembled
      /// first, it is dropped. The default assembles both now.
      virtual double assemble_deferred(const VectorType &v, const bool newton)
      {
        return assemble(v, newton);
      }
      /// As assemble(v, true), with the exact derivative of the residual as
      /// the tangent where the system otherwise uses another linearisation
      /// (the stress-velocity tangent). Its direction descends |r|: the
      /// retry after a line search that found no smaller merit.
      virtual double assemble_exact(const VectorType &v)
      {
        return assemble(v, true);
      }
      /// A force scale for |r| from the last assembly (internal forces).
      virtual double force_scale() const = 0;
      /// Directional derivative of the potential along the last Newton
      /// direction (dv and the corrections of any extra unknowns) with the
      /// last assembled residual: dv . r + (extra terms). Used by the line
      /// search.
      virtual double directional_derivative(const VectorType &dv) const = 0;
      /// Solve K dv = -r with the last assembled K, r (and the corrections
      /// of any extra unknowns). Returns iterations.
      virtual unsigned int solve(VectorType &dv) = 0;
      /// Inexact Newton: the relative residual at which the next solve()
      /// may stop where it iterates (0: the linear solver's own tolerance).
      virtual void set_linear_tolerance(const double /*tolerance*/) {}
      /// Extra unknowns (the blank holder under force control) follow the
      /// line search: their trial values are the accepted ones plus
      /// @p alpha times their last correction. Called before each trial
      /// assembly.
      virtual void set_step_length(const double /*alpha*/) {}
      /// The last trial becomes the accepted iterate (extra unknowns).
      virtual void accept_step() {}
      /// Relative residual and correction of the extra equations (0 if none).
      virtual double extra_residual() const { return 0; }
      /// Residual of the extra equations at the last assembly in the units of
      /// |r| (0 if none). The line search decreases |(r, this)|: with |r|
      /// alone a step that moves only the extra unknowns can never be taken.
      virtual double extra_residual_norm() const { return 0; }
      virtual double extra_correction() const { return 0; }
      /// Whether the contact set changed since the previous call.
      virtual bool contact_set_changed() = 0;
      /// Called at an accepted iterate (after its assembly): a system whose
      /// equations depend on the iterate (adaptive penalty factors) updates
      /// them here and returns the new |r|; -1 if nothing changed. Line-search
      /// trials in between solve one fixed set of equations.
      virtual double update_penalty() { return -1; }
      /// Extra text for the iteration log (e.g. the penalty factor range).
      virtual std::string iteration_info() const { return ""; }
      /// Called once per solve when the iterate is close to convergence
      /// (Contact/Strict check residual): a penalty strategy with a bound
      /// (adaptive-strict) corrects the factors of the nodes deeper than
      /// allowed now, instead of in a re-solve after convergence. Returns the
      /// new |r|, or -1 if nothing changed.
      virtual double correct_penalty() { return -1; }
    };

    struct NewtonReport
    {
      bool         converged         = false;
      unsigned int iterations        = 0;
      unsigned int linear_iterations = 0;
      unsigned int picard_iterations = 0;
      double       residual          = 0;
      bool         corrected         = false; // correct_penalty() changed r
      std::string  failure;
    };

    class NewtonSolver
    {
    public:
      NewtonSolver(const parameters::NonlinearSolver &p,
                   dealii::ConditionalOStream         log);

      /// Iterate from @p v (locally owned entries, constraints satisfied).
      /// Once |r|/|f| <= @p check_residual (> 0) with the contact set
      /// unchanged, the system may correct its penalty factors, once per
      /// solve (NonlinearSystem::correct_penalty()).
      NewtonReport solve(NonlinearSystem             &system,
                         NonlinearSystem::VectorType &v,
                         const double                 check_residual = 0) const;

    private:
      parameters::NonlinearSolver        prm;
      mutable dealii::ConditionalOStream log;
    };
  } // namespace solver
} // namespace formsolve
