// Time-step control: a failed step is retried with a smaller time step; the
// time step grows back after easy steps, or after a run of converged steps
// (Time stepping subsection).
#pragma once

#include <formsolve/parameters/solvers.h>

namespace formsolve
{
  namespace solver
  {
    class StepControl
    {
    public:
      explicit StepControl(const parameters::TimeStepping &p);

      /// The time step to try next (s).
      double time_step() const { return dt; }
      /// A new step begins: its cutback count restarts.
      void begin_step() { step_cutbacks = 0; }
      /// The last try, with time step @p tried, failed: cut the time step.
      /// The cut is from @p tried, which is below time_step() where the step
      /// was shortened to land on a travel; cutting time_step() instead could
      /// retry the same step unchanged. Returns whether another try is
      /// allowed (at or above the minimum, within Max cutbacks).
      bool reject(const double tried);
      /// The step converged in @p iterations Newton iterations: grow the
      /// time step after an easy step without cutbacks, or after Regrowth
      /// after steps such steps in a row.
      void         accept(const unsigned int iterations);
      unsigned int cutbacks() const { return step_cutbacks; }
      /// Continue with time step @p t (a resumed run).
      void set_time_step(const double t) { dt = t; }

    private:
      parameters::TimeStepping prm;
      double                   dt;
      unsigned int             step_cutbacks = 0;
      unsigned int             calm_steps    = 0; // see accept()
    };
  } // namespace solver
} // namespace formsolve
