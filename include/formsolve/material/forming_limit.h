// The forming limit curve (FLC) in true strains and the safety zones of the
// forming limit diagram (doc/theory.md, section 11).
#pragma once

#include <formsolve/parameters/material.h>

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace material
  {
    /// Safety zone of a sheet point, ordered by severity.
    enum class SafetyZone : int
    {
      safe      = 0,
      wrinkling = 1, // minor strain compressive and thickening: eps_1 < -eps_2
      marginal  = 2, // major strain above (1 - margin) FLC
      necking   = 3, // major strain above the FLC
      fracture  = 4  // the deciding damage criterion has reached 1
    };

    std::string zone_name(const SafetyZone z);

    class FormingLimit
    {
    public:
      /// Keeler-Brazier from the hardening exponent and t0 (mm), unless
      /// Material/Forming limit table is given.
      FormingLimit(const parameters::Material &p, const double thickness);

      /// Limit major true strain at minor true strain @p minor.
      double major(const double minor) const;

      /// Zone of a point with strains (minor, major) and deciding damage.
      SafetyZone
      zone(const double minor, const double major, const double damage) const;

      /// FLC0 as a true strain, and where the curve comes from.
      double             plane_strain_limit() const { return major(0.); }
      const std::string &source() const { return origin; }

    private:
      std::vector<std::pair<double, double>> table; // user table, or empty
      double      flc0_engineering = 0;             // Keeler-Brazier, (-)
      double      margin;
      std::string origin;
    };
  } // namespace material
} // namespace formsolve
