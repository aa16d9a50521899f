// What the run takes the sheet to be, said once at its start: the flow
// curve (and whether it is the default material's), the yield criterion,
// the fracture criterion with its constants as given and as used, and
// where the forming limit curve comes from.
#pragma once

#include <formsolve/material/damage.h>
#include <formsolve/material/rigid_viscoplastic.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace material
  {
    /// Screen lines ("flow curve: ...", "forming limit: ...").
    std::vector<std::string> material_summary(const parameters::Material &p,
                                              const RigidViscoplastic    &law,
                                              const DamageCriteria &damage,
                                              const double          thickness);
  } // namespace material
} // namespace formsolve
