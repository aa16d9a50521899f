// The rigid-viscoplastic point law of the flow formulation, on the 3x3 rate
// of deformation of every model (the kinematics supplies the hoop rate in
// axisymmetry).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/flow_stress.h>
#include <formsolve/material/hill48.h>
#include <formsolve/material/mandel.h>

#include <cmath>

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
    ///
    /// With Hill's criterion the law is von Mises's in the mapped rate
    /// S : D (S = hill_map(), doc/theory.md eq. 3b): strain_rate_deviator,
    /// viscosity, beta and the dual rate belong to the mapped rate, the
    /// deviatoric stress is the real one, M s_mapped.
    struct PointResponse
    {
      SymmetricTensor<2, 3> deviatoric_stress;
      SymmetricTensor<2, 3> strain_rate_deviator; // D' (von Mises), S : D
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
      /// The same with Hill's criterion, at a point whose map from the
      /// mapped rate to the current frame is @p map (hill_map()).
      PointResponse evaluate(const SymmetricTensor<2, 3> &strain_rate,
                             const double                 strain_old,
                             const double                 dt,
                             const bool                   newton,
                             const Mandel6x6             &map) const;

      /// Either: Hill's with @p map, von Mises's without (nullptr).
      PointResponse evaluate(const SymmetricTensor<2, 3> &strain_rate,
                             const double                 strain_old,
                             const double                 dt,
                             const bool                   newton,
                             const Mandel6x6             *map) const
      {
        return map ? evaluate(strain_rate, strain_old, dt, newton, *map)
                   : evaluate(strain_rate, strain_old, dt, newton);
      }

      /// M = T(R) S: Hill's root metric S (Hill48::root()) in the orthotropy
      /// frame @p frame (columns RD, TD, ND now), with T the rotation of
      /// symmetric tensors by it: the mapped rate is M^T D, the stress
      /// M s_mapped, the tangent M C_mapped M^T.
      Mandel6x6 hill_map(const dealii::Tensor<2, 3> &frame) const;

      /// The derivative of the deviatoric stress with respect to the rate
      /// of deformation at the point of @p m, in the general form any law
      /// gives (doc/theory.md, eq. 4c): 2 mu P_dev + (beta - beta_plastic)
      /// D' (x) D' + beta_plastic/2 (D' (x) W + W (x) D'), with @p w_rate the
      /// dual direction times its rate (D' for Newton's own tangent).
      SymmetricTensor<4, 3> tangent(const PointResponse         &m,
                                    const SymmetricTensor<2, 3> &w_rate) const;
      /// Hill's: M tangent(m, w_rate) M^T, in Mandel's notation.
      Mandel6x6 tangent(const PointResponse         &m,
                        const SymmetricTensor<2, 3> &w_rate,
                        const Mandel6x6             &map) const;

      /// The equivalent stress sigma_bar of a response, von Mises's or
      /// Hill's (sqrt(3/2) times the norm of the mapped stress).
      static double equivalent_stress(const PointResponse &m)
      {
        const SymmetricTensor<2, 3> s =
          2. * m.viscosity * m.strain_rate_deviator;
        return std::sqrt(1.5 * (s * s));
      }

      /// Whether tangent() is 2 mu P_dev plus terms in D' and W only: the
      /// element then assembles it from products of the shape gradients
      /// (solver::CellTangent::add_deviatoric), the same matrix in 0.55-0.65
      /// of the time of the general 6x6 product (doc/theory.md, section 5a).
      bool isotropic() const { return iso; }

      /// The Hill coefficients (von Mises's when isotropic()).
      const Hill48 &hill() const { return coefficients; }
      /// The angle of RD from x (radians).
      double rolling_direction() const { return rolling; }

      /// K_v in sigma_m = K_v tr(D) (MPa s).
      double bulk_viscosity() const { return bulk; }
      /// The strain rate below which the law is linear (rigid zone), 1/s.
      double cutoff_rate() const { return cutoff; }
      /// Material/Rigid zone = smooth (doc/theory.md eq. 3a).
      bool smooth_rigid_zone() const { return smooth; }

      const FlowStress &flow_stress() const { return law; }

    private:
      /// The law on a strain-rate deviator (mapped, for Hill's).
      PointResponse respond(const SymmetricTensor<2, 3> &e,
                            const double                 strain_old,
                            const double                 dt,
                            const bool                   newton) const;

      FlowStress law;
      Hill48     coefficients;
      Mandel6x6  root; // S in the orthotropy frame
      bool       iso;
      double     rolling;
      double     cutoff; // limiting strain rate
      bool       smooth;
      double     bulk;
    };
  } // namespace material
} // namespace formsolve
