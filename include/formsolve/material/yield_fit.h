// Yld2004-18p's coefficients fitted by least squares to directional test
// data (Material/Yld2004-18p fit): c12, c13, c21, c23, c31, c32 and c66 of
// C' and C'', the exponent fixed (doc/theory.md, section 3b, eq. 3g).
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    struct Anisotropy;
  }

  namespace material
  {
    struct YldFit
    {
      std::vector<double> c1, c2; // nine each: c12 ... c32, c44, c55, c66
      double              rms_stress = 0; // of sigma_theta/sigma_0, sigma_b, ps
      double              rms_r      = 0; // of r_theta and r_b
      unsigned int        evaluations = 0;
      /// "key = value" lines: the coefficients, each datum beside the
      /// fitted law's value, the RMS errors.
      std::string report;
      /// One line: the RMS errors and the coefficients.
      std::string headline;
    };

    /// Levenberg-Marquardt (Eigen) on the relative errors of every datum,
    /// from Material/Yld2004-18p C1, C2. Throws naming the entries if no
    /// set with a positive RD yield stress is reached.
    YldFit fit_yld2004(const parameters::Anisotropy &a);
  } // namespace material
} // namespace formsolve
