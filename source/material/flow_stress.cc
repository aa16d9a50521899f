#include <formsolve/material/flow_stress.h>

#include <cmath>

namespace formsolve
{
  namespace material
  {
    FlowStress::FlowStress(const parameters::Material &p)
        : voce(p.flow_curve == parameters::FlowCurve::voce)
        , K(p.strength_coefficient)
        , n(p.hardening_exponent)
        , eps0(p.prestrain)
        , A(p.voce_saturation)
        , B(p.voce_amplitude)
        , C(p.voce_rate)
        , m(p.rate_sensitivity)
        , rate0(p.reference_strain_rate)
    {}

    double FlowStress::hardening(const double strain) const
    {
      if (voce)
        return A - B * std::exp(-C * strain);
      return K * (n == 0. ? 1. : std::pow(eps0 + strain, n));
    }

    double FlowStress::hardening_slope(const double strain) const
    {
      if (voce)
        return B * C * std::exp(-C * strain);
      return n == 0. ? 0. : n * hardening(strain) / (eps0 + strain);
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
