// The rigid-viscoplastic point law of the flow formulation, on the 3x3 rate
// of deformation of every model (the kinematics supplies the hoop rate in
// axisymmetry).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/flow_stress.h>

namespace formsolve
{
  namespace material
  {
    using dealii::SymmetricTensor;

    /// Stress and tangent at one quadrature point for a given strain rate,
    /// with the strain integrated implicitly: eps = eps_n + dt * rate.
    /// The tangent d(deviatoric stress)/dD = 2 mu P_dev + beta D' (x) D' is
    /// returned by its two scalars, which lets the assembler form element
    /// matrices without fourth-order tensors.
    struct PointResponse
    {
      SymmetricTensor<2, 3> deviatoric_stress;
      SymmetricTensor<2, 3> strain_rate_deviator; // D'
      double                equivalent_strain_rate;
      double                flow_stress;
      double                viscosity; // mu: s' = 2 mu D'
      double                beta;      // 0 for the secant tangent
      // The part of beta from the flow law's direction, -(4/9) s/rate^3,
      // which the stress-velocity linearisation replaces (0: rigid zone).
      double beta_plastic = 0;
      // The rate r_w that scales the dual direction w = D'/r_w of the
      // stress-velocity linearisation: the equivalent strain rate
      // (piecewise law), sqrt(rate^2 + cutoff^2) (smooth law).
      double dual_rate = 0;
    };

    class RigidViscoplastic
    {
    public:
      explicit RigidViscoplastic(const parameters::Material &p);

      /// @p newton false gives the secant (direct-iteration) tangent 2 mu
      /// P_dev.
      PointResponse evaluate(const SymmetricTensor<2, 3> &strain_rate,
                             const double                 strain_old,
                             const double                 dt,
                             const bool                   newton) const;

      /// The derivative of the deviatoric stress with respect to the rate
      /// of deformation at the point of @p m, in the general form any law
      /// gives (doc/theory.md, eq. 4c): 2 mu P_dev + (beta - beta_plastic)
      /// D' (x) D' + beta_plastic/2 (D' (x) W + W (x) D'), with @p w_rate the
      /// dual direction times its rate (D' for Newton's own tangent).
      SymmetricTensor<4, 3> tangent(const PointResponse         &m,
                                    const SymmetricTensor<2, 3> &w_rate) const;

      /// Whether tangent() is 2 mu P_dev plus terms in D' and W only: the
      /// element then assembles it from products of the shape gradients
      /// (solver::CellTangent::add_deviatoric), the same matrix in 0.55-0.65
      /// of the time of the general 6x6 product (doc/theory.md, section 5a).
      bool isotropic() const { return true; }

      /// K_v in sigma_m = K_v tr(D) (MPa s).
      double bulk_viscosity() const { return bulk; }
      /// The strain rate below which the law is linear (rigid zone), 1/s.
      double cutoff_rate() const { return cutoff; }
      /// Material/Rigid zone = smooth (doc/theory.md eq. 3a).
      bool smooth_rigid_zone() const { return smooth; }

      const FlowStress &flow_stress() const { return law; }

    private:
      FlowStress law;
      double     cutoff; // limiting strain rate
      bool       smooth;
      double     bulk;
    };
  } // namespace material
} // namespace formsolve
