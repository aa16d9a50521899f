// Step control: cuts on failure down to the minimum and no further, at most
// Max cutbacks per step, from the step actually tried, grows after easy steps
// without cuts or after Regrowth after steps hard ones in a row, never above
// the nominal time step.
#include <formsolve/newton/step_control.h>

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
  p.regrowth_steps    = 0;

  solver::StepControl c(p);
  c.begin_step();
  test::close("starts at the nominal step", c.time_step(), 1, 0);
  test::close("first cut allowed", c.reject(c.time_step()), 1, 0);
  test::close("first cut halves", c.time_step(), 0.5, 1e-15);
  c.reject(c.time_step()); // 0.25
  c.reject(c.time_step()); // 0.125
  test::close("cut to the minimum, not below", c.reject(c.time_step()), 1, 0);
  test::close("at the minimum", c.time_step(), 0.1, 1e-15);
  test::close("no try below the minimum", c.reject(c.time_step()), 0, 0);
  test::close("cutbacks counted", c.cutbacks(), 5, 0);

  c.accept(3); // converged after cuts: no growth in this step
  test::close("no growth right after cuts", c.time_step(), 0.1, 1e-15);
  c.begin_step();
  for (int i = 0; i < 10; ++i)
    {
      c.begin_step();
      c.accept(6); // not easy
    }
  test::close("no growth after hard steps (Regrowth after steps = 0)",
              c.time_step(),
              0.1,
              1e-15);
  c.begin_step();
  c.accept(5); // easy
  test::close("growth after an easy step", c.time_step(), 0.15, 1e-15);
  for (int i = 0; i < 20; ++i)
    {
      c.begin_step();
      c.accept(1);
    }
  test::close("grows back to the nominal step only", c.time_step(), 1, 1e-15);

  // Hard steps only (10 > 5 iterations): growth after every third one.
  p.regrowth_steps = 3;
  solver::StepControl e(p);
  e.begin_step();
  e.reject(e.time_step()); // 0.5
  e.accept(10);
  for (int i = 0; i < 2; ++i)
    {
      e.begin_step();
      e.accept(10);
    }
  test::close("no growth after two hard steps", e.time_step(), 0.5, 1e-15);
  e.begin_step();
  e.accept(10);
  test::close("growth after three hard ones", e.time_step(), 0.75, 1e-15);
  for (int i = 0; i < 2; ++i)
    {
      e.begin_step();
      e.accept(10);
    }
  test::close("the count restarts after growth", e.time_step(), 0.75, 1e-15);
  e.begin_step();
  e.accept(10);
  test::close("grows to the nominal step", e.time_step(), 1, 1e-15);
  e.begin_step();
  e.reject(e.time_step()); // 0.5, the count restarts
  e.accept(10);
  e.begin_step();
  e.accept(10);
  e.begin_step();
  e.accept(10);
  test::close("a cut restarts the count", e.time_step(), 0.5, 1e-15);

  p.regrowth_steps = 0;
  p.max_cutbacks   = 2;
  solver::StepControl d(p);
  d.begin_step();
  test::close("cut 1 of 2", d.reject(d.time_step()), 1, 0);
  test::close("cut 2 of 2", d.reject(d.time_step()), 1, 0);
  test::close("no third try", d.reject(d.time_step()), 0, 0);

  // A step shortened to land on a travel (0.2 of the nominal 1) fails: the
  // retry is shorter than the step tried, not a cut of the nominal step that
  // would still be longer and so retry the same 0.2.
  p.max_cutbacks = 8;
  solver::StepControl l(p);
  l.begin_step();
  test::close("a shortened step may be retried", l.reject(0.2), 1, 0);
  test::close("cut from the step tried", l.time_step(), 0.1, 1e-15);
  test::close("no cut below the minimum", l.reject(0.1), 0, 0);
  return test::result();
}
