// Subsection "Material/Yld2004-18p fit": the directional test data that
// Yld2004-18p's coefficients are fitted to by least squares when
// Material/Yld2004-18p coefficients = fitted (doc/theory.md, section 3b,
// eq. 3g; material/yield_fit.h does the fit).
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    struct YieldFit
    {
      std::vector<double> angles = {0, 15, 30, 45, 60, 75, 90}; // degrees
      std::vector<double> stress_ratios;        // sigma_theta/sigma_0, or empty
      std::vector<double> r_values;             // r_theta, or empty
      std::vector<double> biaxial_stress_ratio; // sigma_b/sigma_0, 0 or 1
      std::vector<double> biaxial_r_value;      // r_b, 0 or 1
      std::vector<double> plane_strain_ratio;   // sigma_ps/sigma_0 along RD
      unsigned int        starts = 128;         // of the multi-start search

      /// The number of data points (a point at 0 degrees counts once).
      unsigned int size() const;

      /// Declares the entries inside subsection "Yld2004-18p fit".
      void declare(Declarations &d);
      /// @p unknowns: the coefficients to fit, which the data must match
      /// at least in number.
      void validate(const unsigned int unknowns) const;
    };
  } // namespace parameters
} // namespace formsolve
