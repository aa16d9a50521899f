#include <formsolve/material/flow_stress.h>

#include <cmath>

namespace formsolve
{
  namespace material
  {
    FlowStress::FlowStress(const parameters::Material &p)
        : K(p.strength_coefficient)
        , n(p.hardening_exponent)
        , eps0(p.prestrain)
        , m(p.rate_sensitivity)
        , rate0(p.reference_strain_rate)
    {}

    double FlowStress::value(const double strain, const double rate) const
    {
      const double h = (n == 0. ? 1. : std::pow(eps0 + strain, n));
      const double r = (m == 0. ? 1. : std::pow(rate / rate0, m));
      return K * h * r;
    }

    double FlowStress::d_strain(const double strain, const double rate) const
    {
      return n == 0. ? 0. : n * value(strain, rate) / (eps0 + strain);
    }

    double FlowStress::d_rate(const double strain, const double rate) const
    {
      return m == 0. ? 0. : m * value(strain, rate) / rate;
    }
  } // namespace material
} // namespace formsolve
