#include <formsolve/parameters/plausibility.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      /// max over eps of h(eps) exp(-eps) for a tabulated h: at the points,
      /// where it is stationary inside a segment (eps = e0 + 1 - h0/slope),
      /// and along the extrapolation beyond the last point.
      double table_tensile_strength(const Material &m)
      {
        const auto &p    = m.flow_curve_points;
        double      best = 0;
        auto        at   = [&](const double e, const double h) {
          best = std::max(best, h * std::exp(-e));
        };
        for (std::size_t k = 0; k < p.size(); ++k)
          {
            at(p[k].first, p[k].second);
            if (k + 1 < p.size())
              {
                const double slope = (p[k + 1].second - p[k].second) /
                                     (p[k + 1].first - p[k].first);
                const double e = p[k].first + 1 - p[k].second / slope;
                if (slope > 0 && e > p[k].first && e < p[k + 1].first)
                  at(e, p[k].second + slope * (e - p[k].first));
              }
          }
        const auto [e0, s0] = p[p.size() - 2];
        const auto [e1, s1] = p.back();
        const double slope  = (s1 - s0) / (e1 - e0);
        if (m.flow_extrapolation == FlowExtrapolation::power_law && e0 > 0)
          {
            // sigma_N (e/e_N)^n exp(-e) is largest at e = n.
            const double n = std::log(s1 / s0) / std::log(e1 / e0);
            if (n > e1)
              at(n, s1 * std::pow(n / e1, n));
          }
        else if (m.flow_extrapolation != FlowExtrapolation::constant &&
                 slope > 0 && e1 + 1 - s1 / slope > e1)
          at(e1 + 1 - s1 / slope, slope * (1 - s1 / slope) + s1);
        return best;
      }
    } // namespace

    double tensile_strength(const Material &m)
    {
      if (m.tensile_strength > 0)
        return m.tensile_strength;
      if (m.flow_curve == FlowCurve::table)
        return table_tensile_strength(m);
      if (m.flow_curve == FlowCurve::swift_voce ||
          m.flow_curve == FlowCurve::hockett_sherby)
        {
          // No closed form: h e^-eps on a fine grid (the maximum lies below
          // eps = n < 1 for any Swift part of a sheet; 3 covers it).
          const bool   hs   = m.flow_curve == FlowCurve::hockett_sherby;
          const double w    = hs ? 0. : m.swift_weight;
          const double p    = hs ? m.hockett_sherby_exponent : 1.;
          double       best = 0;
          for (unsigned int k = 0; k <= 30000; ++k)
            {
              const double e = 3e-4 * k;
              const double h =
                w * m.strength_coefficient *
                  std::pow(m.prestrain + e, m.hardening_exponent) +
                (1 - w) *
                  (m.voce_saturation -
                   m.voce_amplitude * std::exp(-m.voce_rate * std::pow(e, p)));
              best = std::max(best, h * std::exp(-e));
            }
          return best;
        }
      // Considere: d sigma/d eps = sigma at the uniform strain eps_u; the
      // engineering stress there is sigma(eps_u) exp(-eps_u).
      double eps_u = 0, sigma_u = 0;
      if (m.flow_curve == FlowCurve::voce)
        {
          const double A = m.voce_saturation, B = m.voce_amplitude,
                       C = m.voce_rate;
          eps_u          = B * (C + 1) > A ? std::log(B * (C + 1) / A) / C : 0.;
          sigma_u        = A - B * std::exp(-C * eps_u);
        }
      else
        {
          eps_u   = std::max(m.hardening_exponent - m.prestrain, 0.);
          sigma_u = m.strength_coefficient *
                    std::pow(m.prestrain + eps_u, m.hardening_exponent);
        }
      return sigma_u * std::exp(-eps_u);
    }

    namespace
    {
      /// The entry that sets the flow curve's stress scale, for messages.
      const char *stress_scale_entry(const FlowCurve curve)
      {
        return curve == FlowCurve::voce || curve == FlowCurve::hockett_sherby
                 ? "Material/Voce saturation stress = "
               : curve == FlowCurve::table
                 ? "Material/Flow curve file: its largest stress, "
               : curve == FlowCurve::swift_voce
                 ? "Material/Strength coefficient and Voce "
                   "saturation stress, blended by Swift weight, "
                 : "Material/Strength coefficient = ";
      }
    } // namespace

    SiebelEstimate siebel(const Run &run)
    {
      SiebelEstimate s;
      const auto    &g = run.geometry;
      const auto    &t = run.tools;
      s.applies        = g.blank_shape == BlankShape::round &&
                  t.punch.shape == ToolShape::round && t.blank_holder.enabled &&
                  t.blank_holder.shape == ToolShape::round &&
                  g.blank_diameter > t.blank_holder.diameter;
      if (!s.applies)
        return s;
      const double beta = g.blank_diameter / t.punch.diameter;
      s.pressure =
        0.0025 *
        ((beta - 1) * (beta - 1) + t.punch.diameter / (200 * g.thickness)) *
        tensile_strength(run.material);
      s.area = M_PI / 4 *
               (g.blank_diameter * g.blank_diameter -
                t.blank_holder.diameter * t.blank_holder.diameter);
      s.force = s.pressure * s.area;
      return s;
    }

    std::vector<std::string> plausibility_warnings(const Run &run)
    {
      std::vector<std::string> w;
      const auto               say = [&](auto &&...parts) {
        std::ostringstream s;
        (s << ... << parts);
        w.push_back(s.str());
      };
      const auto &g = run.geometry;
      if (g.thickness < 0.05)
        say("Geometry/Thickness = ",
            g.thickness,
            " mm is thinner than any sheet; lengths are in mm, not m");
      for (const Tool *t :
           {&run.tools.punch, &run.tools.die, &run.tools.blank_holder})
        if (t->enabled && t->shape == ToolShape::round && t->diameter < 1)
          say("Tools/",
              t->name,
              "/Diameter = ",
              t->diameter,
              " mm is smaller than 1 mm; lengths are in mm, not m");
      if (g.blank_shape == BlankShape::round && g.blank_diameter < 1)
        say("Geometry/Blank diameter = ",
            g.blank_diameter,
            " mm is smaller than 1 mm; lengths are in mm, not m");
      const double stress = run.material.stress_scale();
      const auto   curve  = run.material.flow_curve;
      const char  *scale  = stress_scale_entry(curve);
      if (stress < 50)
        say(scale,
            stress,
            " MPa is below 50 MPa, softer than any sheet metal at room "
            "temperature; stresses are in MPa, not GPa");
      if (run.tools.punch_speed < 0.01)
        say("Tools/Punch/Speed = ",
            run.tools.punch_speed,
            " mm/s is below 0.01 mm/s; speeds are in mm/s, not m/s");
      if ((curve == FlowCurve::voce || curve == FlowCurve::table ||
           curve == FlowCurve::hockett_sherby) &&
          run.material.forming_limit_table.empty())
        say("Material/Forming limit table is empty: the forming limit is "
            "Keeler-Brazier's from Material/Hardening exponent = ",
            run.material.hardening_exponent,
            ", which the ",
            curve == FlowCurve::table ? "table" : "Voce curve",
            " does not set; give the sheet's FLC or its n-value");
      if (stress > 1e4)
        say(scale, stress, " MPa is above 10 GPa; stresses are in MPa, not Pa");
      for (const Tool *t :
           {&run.tools.punch, &run.tools.die, &run.tools.blank_holder})
        if (t->enabled && t->friction_coefficient > 0.5)
          say("Tools/",
              t->name,
              "/Friction coefficient = ",
              t->friction_coefficient,
              " is above 0.5, more than lubricated or dry sheet forming "
              "shows (0.02-0.3)");
      // Ironing: the wall passes a gap thinner than the sheet.
      const auto &pu = run.tools.punch, &di = run.tools.die;
      if (pu.enabled && di.enabled && pu.shape == di.shape && pu.has_outline())
        {
          const double clearance =
            pu.shape == ToolShape::round
              ? 0.5 * (di.diameter - pu.diameter)
              : 0.5 * std::min(di.length - pu.length, di.width - pu.width);
          if (clearance < g.thickness)
            say("the clearance between punch and die (",
                clearance,
                " mm per side) is smaller than the sheet thickness (",
                g.thickness,
                " mm): the cup wall will be ironed by ",
                std::round(100 * (1 - clearance / g.thickness)),
                " % or more (deliberate ironing is fine; otherwise check "
                "Tools/Die/Diameter and Tools/Punch/Diameter)");
        }
      const auto  s     = siebel(run);
      const auto &tools = run.tools;
      if (s.applies && tools.holder_control == HolderControl::force &&
          (tools.holder_force.smallest() < 0.1 * s.force ||
           tools.holder_force.largest() > 10 * s.force))
        say("Tools/Blank holder/Force = ",
            tools.holder_force.text(),
            " N is far from Siebel's estimate ",
            std::round(s.force),
            " N (p = ",
            s.pressure,
            " MPa on the initial flange of ",
            s.area,
            " mm^2 with R_m = ",
            tensile_strength(run.material),
            " MPa); the force is in N, for the full part (Force = siebel "
            "sets the estimate)");
      return w;
    }
  } // namespace parameters
} // namespace formsolve
