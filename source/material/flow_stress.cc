#include <deal.II/base/exceptions.h>

#include <formsolve/material/flow_stress.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace material
  {
    FlowStress::FlowStress(const parameters::Material &p)
        : curve(p.flow_curve)
        , extrapolation(p.flow_extrapolation)
        , table(p.flow_curve_points)
        , K(p.strength_coefficient)
        , n(p.hardening_exponent)
        , eps0(p.prestrain)
        , A(p.voce_saturation)
        , B(p.voce_amplitude)
        , C(p.voce_rate)
        , alpha(p.swift_weight)
        , power(p.flow_curve == parameters::FlowCurve::hockett_sherby
                  ? p.hockett_sherby_exponent
                  : 1.)
        , m(p.rate_sensitivity)
        , rate0(p.reference_strain_rate)
    {}

    std::pair<double, double> FlowStress::tabulated(const double strain) const
    {
      using parameters::FlowExtrapolation;
      Assert(table.size() >= 2, dealii::ExcInternalError());
      if (strain < table.front().first)
        return {table.front().second, 0.};
      const auto &[e1, s1] = table.back();
      if (strain >= e1)
        {
          const auto &[e0, s0] = table[table.size() - 2];
          const double slope   = (s1 - s0) / (e1 - e0);
          if (extrapolation == FlowExtrapolation::constant)
            return {s1, 0.};
          if (extrapolation == FlowExtrapolation::last_slope ||
              e0 <= 0) // no log-log slope from a point at zero strain
            return {s1 + slope * (strain - e1), slope};
          const double power = std::log(s1 / s0) / std::log(e1 / e0);
          const double h     = s1 * std::pow(strain / e1, power);
          return {h, power * h / strain};
        }
      // The segment holding strain (the first point with a larger strain).
      const auto k = std::upper_bound(table.begin(),
                                      table.end(),
                                      strain,
                                      [](const double e, const auto &p) {
                                        return e < p.first;
                                      }) -
                     table.begin();
      const auto &[e0, s0] = table[k - 1];
      const auto &[e2, s2] = table[k];
      const double slope   = (s2 - s0) / (e2 - e0);
      return {s0 + slope * (strain - e0), slope};
    }

    std::pair<double, double> FlowStress::saturating(const double strain) const
    {
      if (power == 1.)
        return {A - B * std::exp(-C * strain), B * C * std::exp(-C * strain)};
      // Below eps_c the chord from 0: for p < 1 the slope B C p eps^(p-1)
      // is infinite at 0, and Newton's tangent needs a finite one
      // (doc/theory.md, eq. 2hs).
      constexpr double eps_c = 1e-4;
      if (strain < eps_c)
        {
          const double chord =
            B * (1 - std::exp(-C * std::pow(eps_c, power))) / eps_c;
          return {A - B + chord * std::max(strain, 0.), chord};
        }
      const double e = std::exp(-C * std::pow(strain, power));
      return {A - B * e, B * C * power * std::pow(strain, power - 1) * e};
    }

    double FlowStress::hardening(const double strain) const
    {
      using parameters::FlowCurve;
      const double voce  = saturating(strain).first,
                   swift = K * (n == 0. ? 1. : std::pow(eps0 + strain, n));
      return curve == FlowCurve::voce || curve == FlowCurve::hockett_sherby
               ? voce
             : curve == FlowCurve::table ? tabulated(strain).first
             : curve == FlowCurve::swift_voce
               ? alpha * swift + (1 - alpha) * voce
               : swift;
    }

    double FlowStress::hardening_slope(const double strain) const
    {
      using parameters::FlowCurve;
      const double voce = saturating(strain).second,
                   swift =
                     n == 0. ? 0. : n * K * std::pow(eps0 + strain, n - 1);
      return curve == FlowCurve::voce || curve == FlowCurve::hockett_sherby
               ? voce
             : curve == FlowCurve::table ? tabulated(strain).second
             : curve == FlowCurve::swift_voce
               ? alpha * swift + (1 - alpha) * voce
               : swift;
    }

    double FlowStress::value(const double strain, const double rate) const
    {
      const double r = (m == 0. ? 1. : std::pow(rate / rate0, m));
      return hardening(strain) * r;
    }

    double FlowStress::d_strain(const double strain, const double rate) const
    {
      const double r = (m == 0. ? 1. : std::pow(rate / rate0, m));
      return hardening_slope(strain) * r;
    }

    double FlowStress::d_rate(const double strain, const double rate) const
    {
      return m == 0. ? 0. : m * value(strain, rate) / rate;
    }
  } // namespace material
} // namespace formsolve
