#include <formsolve/newton/step_control.h>

#include <algorithm>

namespace formsolve
{
  namespace solver
  {
    StepControl::StepControl(const parameters::TimeStepping &p)
        : prm(p)
        , dt(p.time_step)
    {}

    bool StepControl::reject(const double tried)
    {
      ++step_cutbacks;
      const double from = std::min(dt, tried);
      // One last try at the minimum itself before giving up.
      if (from > prm.minimum_time_step * (1 + 1e-12))
        dt = std::max(from * prm.cutback_factor, prm.minimum_time_step);
      else
        return false;
      return step_cutbacks <= prm.max_cutbacks;
    }

    void StepControl::accept(const unsigned int iterations)
    {
      // Calm steps: converged in a row without a cut, since the last growth.
      calm_steps = step_cutbacks == 0 ? calm_steps + 1 : 0;
      if (step_cutbacks == 0 && dt < prm.time_step &&
          (iterations <= prm.easy_iterations ||
           (prm.regrowth_steps > 0 && calm_steps >= prm.regrowth_steps)))
        {
          dt         = std::min(dt * prm.growth_factor, prm.time_step);
          calm_steps = 0;
        }
    }
  } // namespace solver
} // namespace formsolve
