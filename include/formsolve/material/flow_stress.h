// Flow stress of the sheet: strain hardening and rate sensitivity.
#pragma once

#include <formsolve/parameters/parameters.h>

namespace formsolve
{
  namespace material
  {
    /// sigma_bar = K (eps0 + eps)^n (rate / rate0)^m   (doc/theory.md, eq. 2)
    class FlowStress
    {
    public:
      explicit FlowStress(const parameters::Material &p);

      double value(const double strain, const double rate) const;
      double d_strain(const double strain, const double rate) const;
      double d_rate(const double strain, const double rate) const;

    private:
      double K, n, eps0, m, rate0;
    };
  } // namespace material
} // namespace formsolve
