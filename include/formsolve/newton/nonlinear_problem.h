// What Newton's method (solver/newton_solver.h) needs from a discrete
// problem: evaluations along the direction from the current iterate, the
// direction, the hand-over of an iterate, and a chance to tighten the
// equations near convergence. The problem owns its unknowns, residual and
// tangent; Newton only steers. A problem may carry extra unknowns besides
// the main ones (a force-controlled tool's velocity): Newton sees them only
// through the norms below.
#pragma once

#include <cmath>
#include <string>

namespace formsolve
{
  namespace solver
  {
    /// The linearisation a tangent is assembled with: Newton's, the secant
    /// one of a direct (Picard) iteration, or the exact derivative of the
    /// residual where Newton's is another (the retry after a stalled line
    /// search).
    enum class Linearisation
    {
      newton,
      secant,
      exact
    };

    /// The norms of one evaluation.
    struct Evaluation
    {
      double residual = 0; // |r| of the main equations (N)
      /// |r| of the extra equations, in the units of residual (0 if none).
      double extra = 0;
      /// The same against the extra equations' own scale (-).
      double extra_relative = 0;
      double scale          = 1; // force scale for |r|
      /// g(alpha) = dx . r + (extra terms) along the last direction: the
      /// directional derivative of the potential (0 before any direction).
      double slope = 0;

      /// What the line search decreases: without the extra residual a step
      /// that moves only the extra unknowns could never be taken.
      double merit() const { return std::hypot(residual, extra); }
      double relative() const { return residual / std::max(scale, 1e-300); }
    };

    /// A new direction from the current iterate.
    struct Direction
    {
      unsigned int linear_iterations = 0;
      double       norm              = 0; // |dx|
      double       full_step_norm    = 0; // |x + dx|
      /// The extra unknowns' correction, relative to them (-).
      double extra_relative = 0;
      double slope          = 0; // g(0)
    };

    /// An iterate, once accepted.
    struct Accepted
    {
      /// Its norms; new ones if its equations changed with it (adaptive
      /// penalty factors).
      Evaluation evaluation;
      /// Whether the set of active constraints differs from the last
      /// accepted iterate's.
      bool   active_set_changed = false;
      double norm               = 0; // |x|
      /// The last correction of the extra unknowns, relative to the new
      /// iterate's (-).
      double extra_relative = 0;
    };

    class NonlinearProblem
    {
    public:
      virtual ~NonlinearProblem() = default;

      /// Evaluates the trial x + alpha dx (alpha = 0: the iterate itself;
      /// before any direction, dx = 0). With @p tangent_now the tangent of
      /// @p kind is assembled with the residual (it is expected to give the
      /// next direction); else only when solve() or the problem itself asks
      /// for it, linearised as the last tangent was.
      virtual Evaluation evaluate(const double        alpha,
                                  const Linearisation kind,
                                  const bool          tangent_now) = 0;

      /// The direction dx from the current iterate: K dx = -r, solved to the
      /// relative residual @p tolerance where the linear solver iterates (0:
      /// its own). Throws if the solve fails.
      virtual Direction solve(const double tolerance) = 0;

      /// The last evaluated trial becomes the iterate.
      virtual Accepted accept() = 0;

      /// Near convergence, once per solve: the problem may tighten its
      /// equations (a bound on the penalty factors). Returns true, with
      /// @p evaluation the iterate's new norms, if they changed.
      virtual bool tighten(Evaluation &evaluation) = 0;

      /// Extra text for the iteration log.
      virtual std::string info() const { return ""; }
    };
  } // namespace solver
} // namespace formsolve
