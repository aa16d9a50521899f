// The sheet's plastic anisotropy, entries of the "Material" subsection: the
// yield criterion (von Mises, Hill 1948, Barlat's Yld2004-18p or Hosford),
// Hill's calibration (r-values or directional yield stresses), Yld2004-18p's
// coefficients and exponent, the transverse shear coefficients, the rolling
// direction, and the normalisation the fracture constants were calibrated in
// (doc/theory.md, sections 3a, 3b).
#pragma once

#include <formsolve/parameters/yield_fit.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class YieldCriterion
    {
      von_mises,
      hill48,
      yld2004_18p, // Barlat et al. 2005: C', C'' and the exponent
      hosford      // isotropic, |s1 - s2|^a + ...: Yld2004-18p, C = 1
    };

    enum class HillCalibration
    {
      r_values,      // r0, r45, r90 (or one normal r)
      yield_stresses // sigma45/sigma0, sigma90/sigma0 (and sigma_b/sigma0)
    };

    /// Where Yld2004-18p's coefficients come from.
    enum class YldCoefficients
    {
      given, // Yld2004-18p C1, C2 as entered
      fitted // least squares to subsection Yld2004-18p fit, from C1, C2
    };

    /// Hill's L and M (the shear coefficients of the planes through ND),
    /// which neither r-values nor in-plane yield stresses fix.
    enum class TransverseShear
    {
      equal_to_n, // L = M = N
      isotropic   // L = M = 3/2, von Mises's
    };

    /// The equivalent stress and strain the fracture constants (Oyane a, b;
    /// the Cockcroft-Latham critical value) were calibrated in.
    enum class DamageNormalisation
    {
      // Hill's normal anisotropy with sigma_bar^2 = 3/(2(2+r)) [r(s1-s2)^2
      // + (s2-s3)^2 + (s3-s1)^2]: the published constants of the reference
      // materials; converted to formsolve's G + H = 1.
      normal_anisotropy,
      // formsolve's own: sigma_bar is the RD uniaxial flow stress.
      rolling_direction
    };

    struct Anisotropy
    {
      YieldCriterion      criterion   = YieldCriterion::von_mises;
      HillCalibration     calibration = HillCalibration::r_values;
      std::vector<double> r_values    = {1.};
      std::vector<double> yield_stress_ratios; // empty: not given
      // c12, c13, c21, c23, c31, c32, (c44, c55,) c66 of C' and C''.
      std::vector<double> yld_c1         = {1, 1, 1, 1, 1, 1, 1};
      std::vector<double> yld_c2         = {1, 1, 1, 1, 1, 1, 1};
      double              yield_exponent = 8;
      YldCoefficients     yld_source     = YldCoefficients::given;
      YieldFit            fit;
      TransverseShear     transverse_shear  = TransverseShear::equal_to_n;
      double              rolling_direction = 0; // degrees from x, 3-D
      DamageNormalisation damage_normalisation =
        DamageNormalisation::normal_anisotropy;

      /// Whether the data vary in the sheet plane (earing; 3-D models only).
      /// Yld2004-18p counts as planar unless all its coefficients are 1.
      bool planar() const;
      /// Whether the criterion is one of the non-quadratic ones, whose
      /// stress follows from a local solve (material/yield_dual.h).
      bool non_quadratic() const;
      /// The nine coefficients c12, c13, c21, c23, c31, c32, c44, c55, c66
      /// of C' (@p which 1) or C'' (2): all ones for Hosford; c44 = c55 = 1
      /// where seven are given.
      std::vector<double> yld_coefficients(const unsigned int which) const;
      /// The calibration's name and data, for messages and the summary.
      std::string describe() const;

      /// Entries inside subsection "Material".
      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
