// The point law of the springback release (doc/theory.md, section 12):
// isotropic linear elasticity on top of the end-of-forming stress, with a
// return to the yield surface of the sheet's criterion (von Mises or Hill's,
// sigma_bar^2 = sigma : P : sigma in the current frame) where the released
// stress would leave it, hardening by the flow curve at the reference rate.
// The closest-point return of a quadratic criterion reduces to one scalar:
// sigma = (I + 2 G gamma P)^-1 : sigma_trial.
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <formsolve/material/flow_stress.h>
#include <formsolve/material/hill48.h>

namespace formsolve
{
  namespace material
  {
    using dealii::SymmetricTensor;

    class ReleaseLaw
    {
    public:
      /// Needs Material/Young's modulus.
      explicit ReleaseLaw(const parameters::Material &p);

      struct Response
      {
        SymmetricTensor<2, 3> stress;
        SymmetricTensor<4, 3> tangent;            // d stress / d strain
        double                trial_ratio    = 0; // sigma_bar_trial / sigma_y
        double                plastic_strain = 0; // of the release (-)
        bool                  yielded        = false;
      };

      /// The stress of the release strain @p strain on top of @p end_stress
      /// at a point of equivalent plastic strain @p eq_strain, with the
      /// criterion's metric @p P (metric()).
      Response respond(const SymmetricTensor<2, 3> &end_stress,
                       const SymmetricTensor<2, 3> &strain,
                       const double                 eq_strain,
                       const SymmetricTensor<4, 3> &P) const;

      /// P in the current frame: Hill's rotated by the orthotropy frame
      /// @p frame (columns RD, TD, ND), or von Mises's 3/2 P_dev if the
      /// criterion is isotropic (@p frame may then be anything).
      SymmetricTensor<4, 3> metric(const dealii::Tensor<2, 3> &frame) const;

      /// sqrt(s : P : s).
      static double equivalent(const SymmetricTensor<2, 3> &s,
                               const SymmetricTensor<4, 3> &P);

      /// The yield stress after @p eq_strain: the flow curve at the
      /// reference strain rate (MPa).
      double yield_stress(const double eq_strain) const;

      double                       young_modulus() const { return E; }
      double                       shear_modulus() const { return G; }
      const SymmetricTensor<4, 3> &elasticity() const { return C; }

    private:
      /// gamma of the return from @p trial (sigma_bar_trial > sigma_y).
      double return_parameter(const SymmetricTensor<2, 3> &trial,
                              const double                 eq_strain,
                              const SymmetricTensor<4, 3> &P) const;

      FlowStress            law;
      double                rate0;
      bool                  isotropic;
      SymmetricTensor<4, 3> hill_primal; // P in the orthotropy frame
      double                E, G, K;
      SymmetricTensor<4, 3> C;
    };
  } // namespace material
} // namespace formsolve
