// Flow stress of the sheet: strain hardening and rate sensitivity.
#pragma once

#include <formsolve/parameters/parameters.h>

#include <utility>
#include <vector>

namespace formsolve
{
  namespace material
  {
    /// sigma_bar = h(eps) (rate / rate0)^m with Swift's h = K (eps0 + eps)^n,
    /// Voce's h = A - B exp(-C eps), their blend alpha Swift + (1 - alpha)
    /// Voce, Hockett-Sherby's A - B exp(-C eps^p), or a table's h, linear
    /// between its
    /// points and continued by Flow curve extrapolation   (doc/theory.md,
    /// eq. 2)
    class FlowStress
    {
    public:
      explicit FlowStress(const parameters::Material &p);

      double value(const double strain, const double rate) const;
      double d_strain(const double strain, const double rate) const;
      double d_rate(const double strain, const double rate) const;

    private:
      /// h(eps) and dh/deps.
      double hardening(const double strain) const;
      double hardening_slope(const double strain) const;

      /// Voce's or Hockett-Sherby's h and dh/deps (p = 1: Voce).
      std::pair<double, double> saturating(const double strain) const;
      /// The table's h and dh/deps at @p strain.
      std::pair<double, double> tabulated(const double strain) const;

      parameters::FlowCurve                  curve;
      parameters::FlowExtrapolation          extrapolation;
      std::vector<std::pair<double, double>> table; // (eps, h)
      double K, n, eps0, A, B, C, alpha, power, m, rate0;
    };
  } // namespace material
} // namespace formsolve
