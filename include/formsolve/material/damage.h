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

      /// Increments over a step with deviatoric stress @p s, mean stress
      /// @p mean (MPa, tension positive) and equivalent strain increment
      /// @p d_strain.
      DamageIncrement increment(const dealii::SymmetricTensor<2, 3> &s,
                                const double                         mean,
                                const double d_strain) const;

      /// C = W / C_crit; 0 if C_crit is not set.
      double cockcroft_latham(const double integral) const
      {
        return critical > 0 ? integral / critical : 0.;
      }

      /// The value of the deciding criterion (fracture at 1), from the
      /// history values I and W; 0 with no criterion.
      double deciding(const double oyane, const double integral) const;

      parameters::FractureCriterion criterion() const { return which; }

    private:
      double                        a, b, critical;
      parameters::FractureCriterion which;
    };
  } // namespace material
} // namespace formsolve
