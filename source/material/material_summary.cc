#include <formsolve/material/forming_limit.h>
#include <formsolve/material/material_summary.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    std::vector<std::string> material_summary(const parameters::Material &p,
                                              const RigidViscoplastic    &law,
                                              const DamageCriteria &damage,
                                              const double          thickness)
    {
      std::vector<std::string> lines;
      std::ostringstream       flow;
      if (p.flow_curve == parameters::FlowCurve::voce)
        flow << "flow curve: Voce, sigma = " << p.voce_saturation << " - "
             << p.voce_amplitude << " exp(-" << p.voce_rate << " eps) MPa";
      else if (p.flow_curve == parameters::FlowCurve::hockett_sherby)
        flow << "flow curve: Hockett-Sherby, sigma = " << p.voce_saturation
             << " - " << p.voce_amplitude << " exp(-" << p.voce_rate << " eps^"
             << p.hockett_sherby_exponent << ") MPa";
      else if (p.flow_curve == parameters::FlowCurve::swift_voce)
        flow << "flow curve: Swift-Voce, sigma = " << p.swift_weight << " "
             << p.strength_coefficient << " (" << p.prestrain << " + eps)^"
             << p.hardening_exponent << " + " << 1 - p.swift_weight << " ("
             << p.voce_saturation << " - " << p.voce_amplitude << " exp(-"
             << p.voce_rate << " eps)) MPa";
      else if (p.flow_curve == parameters::FlowCurve::table)
        {
          const auto &t = p.flow_curve_points;
          flow << "flow curve: table of " << t.size() << " points ("
               << p.flow_curve_file << "), " << t.front().second << " MPa at "
               << t.front().first << " to " << t.back().second << " MPa at "
               << t.back().first << ", linear in between, beyond: "
               << (p.flow_extrapolation ==
                       parameters::FlowExtrapolation::power_law
                     ? "power law"
                   : p.flow_extrapolation ==
                       parameters::FlowExtrapolation::last_slope
                     ? "last slope"
                     : "constant");
        }
      else
        {
          flow << "flow curve: Swift, sigma = " << p.strength_coefficient
               << " (" << p.prestrain << " + eps)^" << p.hardening_exponent
               << " MPa";
          // The declared defaults are material B of the reference scene.
          const parameters::Material d;
          if (p.strength_coefficient == d.strength_coefficient &&
              p.hardening_exponent == d.hardening_exponent &&
              p.prestrain == d.prestrain)
            flow << " (Material's defaults: material B of the reference "
                    "scene, type 430 stainless steel)";
        }
      if (p.rate_sensitivity > 0)
        flow << " times (rate/" << p.reference_strain_rate << ")^"
             << p.rate_sensitivity;
      lines.push_back(flow.str());

      if (!law.isotropic())
        {
          std::string hill = law.criterion_summary();
          for (std::size_t k = hill.find('\n'); k != std::string::npos;
               k             = hill.find('\n', k))
            hill.replace(k, 1, ", ");
          std::ostringstream s;
          s << "yield criterion: " << p.anisotropy.describe() << ": " << hill
            << "; RD at " << p.anisotropy.rolling_direction << " deg to x";
          lines.push_back(s.str());
          if (law.non_quadratic() &&
              !law.non_quadratic()->fit_headline().empty())
            lines.push_back(law.non_quadratic()->fit_headline());
        }

      std::ostringstream f;
      const double       k = damage.conversion();
      switch (p.fracture)
        {
          case parameters::FractureCriterion::none:
            f << "fracture criterion: none (Material/Fracture criterion)";
            break;
          case parameters::FractureCriterion::oyane:
            f << "fracture criterion: Oyane, a = " << p.oyane_a
              << ", b = " << p.oyane_b << " as given";
            if (k != 1)
              f << ", used as a = " << damage.a_used()
                << ", b = " << damage.b_used() << " (converted from "
                << "Hill's normal-anisotropy normalisation with k = " << k
                << ")";
            break;
          case parameters::FractureCriterion::cockcroft_latham:
            f << "fracture criterion: Cockcroft-Latham, C_crit = "
              << p.cockcroft_latham << " MPa as given";
            if (k != 1)
              f << ", used as " << damage.critical_used() << " MPa (k = " << k
                << ")";
            break;
        }
      lines.push_back(f.str());

      const FormingLimit flc(p, thickness);
      std::ostringstream l;
      l << "forming limit: " << flc.source();
      if (!p.forming_limit_table.empty())
        l << ": FLC0 = " << flc.plane_strain_limit() << " (true strain)";
      lines.push_back(l.str());
      return lines;
    }
  } // namespace material
} // namespace formsolve
