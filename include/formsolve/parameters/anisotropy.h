// The sheet's plastic anisotropy, entries of the "Material" subsection: the
// yield criterion (von Mises or Hill 1948), its calibration (r-values or
// directional yield stresses), the transverse shear coefficients, the rolling
// direction, and the normalisation the fracture constants were calibrated in
// (doc/theory.md, section 3a).
#pragma once

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
      hill48
    };

    enum class HillCalibration
    {
      r_values,      // r0, r45, r90 (or one normal r)
      yield_stresses // sigma45/sigma0, sigma90/sigma0 (and sigma_b/sigma0)
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
      TransverseShear     transverse_shear  = TransverseShear::equal_to_n;
      double              rolling_direction = 0; // degrees from x, 3-D
      DamageNormalisation damage_normalisation =
        DamageNormalisation::normal_anisotropy;

      /// Whether the data vary in the sheet plane (earing; 3-D models only).
      bool planar() const;
      /// The calibration's name and data, for messages and the summary.
      std::string describe() const;

      /// Entries inside subsection "Material".
      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
