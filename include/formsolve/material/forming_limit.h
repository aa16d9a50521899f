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
    /// The zones of the forming limit diagram, ordered by severity: a point
    /// is in the most severe one whose condition it meets (true strains,
    /// major >= minor; doc/theory.md, section 11).
    enum class SafetyZone : int
    {
      safe                 = 0,
      insufficient_stretch = 1, // stretched, major below the threshold
      wrinkling            = 2, // thickening: major + minor < 0
      compression          = 3, // both strains negative
      severe_thinning      = 4, // 1 - exp(-(major + minor)) above the limit
      risk_of_crack        = 5, // major at or above (1 - margin) FLC
      crack                = 6, // major at or above the FLC
      fracture             = 7  // the deciding damage criterion reached 1
    };
    constexpr unsigned int n_safety_zones = 8;

    /// "risk of crack", ...; and the same as a column name,
    /// "risk_of_crack".
    std::string zone_name(const SafetyZone z);
    std::string zone_key(const SafetyZone z);

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
      double      margin, thinning, stretch;
      std::string origin;
    };
  } // namespace material
} // namespace formsolve
