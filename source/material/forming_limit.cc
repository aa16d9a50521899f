#include <formsolve/material/forming_limit.h>
#include <formsolve/parameters/number_pairs.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    std::string zone_name(const SafetyZone z)
    {
      switch (z)
        {
          case SafetyZone::safe:
            return "safe";
          case SafetyZone::insufficient_stretch:
            return "insufficient stretch";
          case SafetyZone::wrinkling:
            return "wrinkling tendency";
          case SafetyZone::compression:
            return "compression";
          case SafetyZone::severe_thinning:
            return "severe thinning";
          case SafetyZone::risk_of_crack:
            return "risk of crack";
          case SafetyZone::crack:
            return "crack";
          case SafetyZone::fracture:
            return "fracture";
        }
      return "";
    }

    std::string zone_key(const SafetyZone z)
    {
      std::string k = zone_name(z);
      std::replace(k.begin(), k.end(), ' ', '_');
      return k;
    }

    FormingLimit::FormingLimit(const parameters::Material &p,
                               const double                thickness)
        : table(p.forming_limit_table)
        , margin(p.safety_margin)
        , thinning(p.severe_thinning)
        , stretch(p.insufficient_stretch)
    {
      if (!table.empty())
        {
          origin = "table (Material/Forming limit table)";
          return;
        }
      // Keeler-Brazier: FLC0 in engineering major strain (%) = (23.3 + 14.13
      // t) n / 0.21, t in mm (stated for t up to about 3 mm and n <= 0.21).
      const double t   = std::min(thickness, 3.);
      const double n   = std::min(p.hardening_exponent, 0.21);
      flc0_engineering = (23.3 + 14.13 * t) * n / 0.21 / 100.;
      std::ostringstream s;
      s << "Keeler-Brazier, n = " << n;
      if (n != p.hardening_exponent)
        s << " (the hardening exponent " << p.hardening_exponent
          << " capped at 0.21, the rule's range)";
      s << ", t0 = " << thickness
        << " mm: FLC0 = " << std::log1p(flc0_engineering) << " (true strain; "
        << 100 * flc0_engineering << " % engineering)";
      origin = s.str();
    }

    double FormingLimit::major(const double minor) const
    {
      if (!table.empty())
        return parameters::piecewise_linear(table, minor);
      const double flc0 = std::log1p(flc0_engineering);
      if (minor <= 0)
        return flc0 - minor; // constant thinning in true strains
      // Slope 0.6 in engineering strains, minor engineering strain <= 20 %.
      const double e2 = std::min(std::expm1(minor), 0.2);
      return std::log1p(flc0_engineering + 0.6 * e2);
    }

    SafetyZone FormingLimit::zone(const double minor,
                                  const double major_strain,
                                  const double damage) const
    {
      if (damage >= 1)
        return SafetyZone::fracture;
      const double limit = major(minor);
      if (major_strain >= limit)
        return SafetyZone::crack;
      if (major_strain >= (1 - margin) * limit)
        return SafetyZone::risk_of_crack;
      if (1 - std::exp(-(major_strain + minor)) > thinning)
        return SafetyZone::severe_thinning;
      if (major_strain < 0)
        return SafetyZone::compression;
      if (major_strain + minor < 0)
        return SafetyZone::wrinkling;
      if (major_strain < stretch)
        return SafetyZone::insufficient_stretch;
      return SafetyZone::safe;
    }
  } // namespace material
} // namespace formsolve
