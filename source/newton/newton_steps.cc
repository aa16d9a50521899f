#include <formsolve/newton/newton_steps.h>

#include <algorithm>

namespace formsolve
{
  namespace solver
  {
    ErrorEstimate::ErrorEstimate(const parameters::CorrectionMeasure measure)
        : measure(measure)
    {}

    double ErrorEstimate::factor(const double step,
                                 const double extra_step,
                                 const bool   full) const
    {
      if (measure == parameters::CorrectionMeasure::contraction && full &&
          last_full && last_step > 0)
        {
          const double theta =
            std::max(step / last_step,
                     last_extra > 0 ? extra_step / last_extra : 0.);
          if (theta <= 0.5)
            return theta / (1 - theta);
        }
      return 1.;
    }

    void ErrorEstimate::record(const double step,
                               const double extra_step,
                               const bool   full)
    {
      last_full  = full;
      last_step  = step;
      last_extra = extra_step;
    }

    double linear_tolerance(const parameters::NonlinearSolver &p,
                            const double                       rel,
                            const bool                         tight)
    {
      return tight ? 0.
                   : std::min(0.1,
                              std::max(p.forcing * rel,
                                       0.5 * p.residual_tolerance /
                                         std::max(rel, 1e-300)));
    }

    PicardSchedule::PicardSchedule(const parameters::NonlinearSolver &p)
        : initial(p.picard_iterations)
        , now(p.picard_iterations > 0)
    {}

    bool PicardSchedule::newton_next(const unsigned int it) const
    {
      return left == 0 && it >= initial;
    }

    void PicardSchedule::advance(const unsigned int it, const bool fall_back)
    {
      const bool newton = newton_next(it);
      if (left > 0)
        --left;
      if (fall_back)
        left = 3;
      now = !newton || left > 0;
    }

    StallPolicy::StallPolicy(const bool inexact, const bool picard_fallback)
        : tight_solves(!inexact)
        , picard_fallback(picard_fallback)
    {}

    StallResponse StallPolicy::respond(const bool stalled,
                                       const bool descends,
                                       const bool newton_next)
    {
      StallResponse r;
      // Taking an inexact direction that failed (the full step where
      // g0 >= 0, a direct iteration after a stall) let a 262k-DoF step
      // diverge to |r|/|f| = 2e8 (doc/performance.md).
      r.rejected   = !tight_solves && (stalled || !descends);
      tight_solves = tight_solves || r.rejected;
      // The stress-velocity tangent is not the derivative of r: its
      // direction need not descend |r|, the exact tangent's does where r is
      // smooth. If that stalls too: direct iterations, then Newton again.
      r.retry      = !r.rejected && stalled && !last_stalled;
      last_stalled = stalled && !r.rejected;
      r.fallback =
        !r.rejected && !r.retry && stalled && newton_next && picard_fallback;
      return r;
    }
  } // namespace solver
} // namespace formsolve
