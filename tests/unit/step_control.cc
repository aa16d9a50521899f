// Step control: cuts on failure down to the minimum and no further, at most
// Max cutbacks per step, grows only after easy steps without cuts, never
// above the nominal time step.
#include <formsolve/solver/step_control.h>

#include "check.h"

using namespace formsolve;

int main()
{
  parameters::TimeStepping p;
  p.time_step         = 1;
  p.minimum_time_step = 0.1;
  p.cutback_factor    = 0.5;
  p.growth_factor     = 1.5;
  p.easy_iterations   = 5;
  p.max_cutbacks      = 8;

  solver::StepControl c(p);
  c.begin_step();
  test::close("starts at the nominal step", c.time_step(), 1, 0);
  test::close("first cut allowed", c.reject(), 1, 0);
  test::close("first cut halves", c.time_step(), 0.5, 1e-15);
  c.reject(); // 0.25
  c.reject(); // 0.125
  test::close("cut to the minimum, not below", c.reject(), 1, 0);
  test::close("at the minimum", c.time_step(), 0.1, 1e-15);
  test::close("no try below the minimum", c.reject(), 0, 0);
  test::close("cutbacks counted", c.cutbacks(), 5, 0);

  c.accept(3); // converged after cuts: no growth in this step
  test::close("no growth right after cuts", c.time_step(), 0.1, 1e-15);
  c.begin_step();
  c.accept(6); // not easy
  test::close("no growth after a hard step", c.time_step(), 0.1, 1e-15);
  c.begin_step();
  c.accept(5); // easy
  test::close("growth after an easy step", c.time_step(), 0.15, 1e-15);
  for (int i = 0; i < 20; ++i)
    {
      c.begin_step();
      c.accept(1);
    }
  test::close("grows back to the nominal step only", c.time_step(), 1, 1e-15);

  p.max_cutbacks = 2;
  solver::StepControl d(p);
  d.begin_step();
  test::close("cut 1 of 2", d.reject(), 1, 0);
  test::close("cut 2 of 2", d.reject(), 1, 0);
  test::close("no third try", d.reject(), 0, 0);
  return test::result();
}
