// Ductile-fracture criteria integrated along the strain path at every
// quadrature point (doc/theory.md, section 11): Oyane and Cockcroft-Latham.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/parameters/material.h>

namespace formsolve
{
  namespace material
  {
    struct DamageIncrement
    {
      double oyane            = 0; // dI = (1/b)(sigma_m/sigma_bar + a) d eps
      double cockcroft_latham = 0; // dW = max(sigma_1, 0) d eps (MPa)
    };

    class DamageCriteria
    {
    public:
      explicit DamageCriteria(const parameters::Material &p);
      /// With the criterion's mean r-value (r0 + 2 r45 + r90)/4 known, as
      /// the point law has it: no second fit of a fitted Yld2004-18p set.
      DamageCriteria(const parameters::Material &p, const double mean_r);

      /// Increments over a step with deviatoric stress @p s, mean stress
      /// @p mean (MPa, tension positive), equivalent stress @p equivalent
      /// and equivalent strain increment @p d_strain (von Mises's or
      /// Hill's, G + H = 1).
      DamageIncrement increment(const dealii::SymmetricTensor<2, 3> &s,
                                const double                         mean,
                                const double                         equivalent,
                                const double d_strain) const;

      /// The constants as used, after the conversion from the
      /// normalisation they were calibrated in (Material/Fracture constants
      /// normalisation): a/k, b/k^2, C_crit/k.
      double a_used() const { return a; }
      double b_used() const { return b; }
      double critical_used() const { return critical; }
      /// k = sqrt(2(2+r)/(3(1+r))) of that conversion (1: none).
      double conversion() const { return k; }

      /// C = W / C_crit; 0 if C_crit is not set.
      double cockcroft_latham(const double integral) const
      {
        return critical > 0 ? integral / critical : 0.;
      }

      /// The value of the deciding criterion (fracture at 1), from the
      /// history values I and W; 0 with no criterion.
      double deciding(const double oyane, const double integral) const;

      parameters::FractureCriterion criterion() const { return which; }
      /// Where increment()'s mean stress comes from (Material/Fracture mean
      /// stress).
      parameters::MeanStress mean_stress() const { return mean; }

    private:
      double                        k, a, b, critical;
      parameters::FractureCriterion which;
      parameters::MeanStress        mean;
    };
  } // namespace material
} // namespace formsolve
