// The scene of the adaptive-penalty unit tests: one flat, frictionless punch
// with allowed penetration @p delta (no die, no holder), and the adaptive
// strategy's parameters without damping, aiming at delta itself, factors not
// frozen; each test sets its own bounds and update mode on top.
#pragma once

#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/tools.h>

namespace test
{
  inline formsolve::parameters::Tools flat_punch_only(const double delta)
  {
    formsolve::parameters::Tools t;
    t.punch.shape                = formsolve::parameters::ToolShape::flat;
    t.punch.friction_coefficient = 0;
    t.punch.allowed_penetration  = delta;
    t.die.enabled                = false;
    t.blank_holder.enabled       = false;
    return t;
  }

  inline formsolve::parameters::Contact undamped_adaptive(const double delta)
  {
    formsolve::parameters::Contact c;
    c.penalty_factor      = 1;
    c.allowed_penetration = delta;
    c.freeze              = false;
    c.damping             = 1e300; // no damping: test the estimate
    c.target_fraction     = 1;     // the published method aims at delta
    return c;
  }
} // namespace test
