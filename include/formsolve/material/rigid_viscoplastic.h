// The rigid-viscoplastic point law of the flow formulation, on the 3x3 rate
// of deformation of every model (the kinematics supplies the hoop rate in
// axisymmetry).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/flow_stress.h>
#include <formsolve/material/hill48.h>
#include <formsolve/material/mandel.h>
#include <formsolve/material/yield_dual.h>
#include <formsolve/material/yld2004.h>

#include <cmath>
#include <optional>

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
    ///
    /// With a non-quadratic criterion (Yld2004-18p, Hosford) the map is the
    /// rotation to the orthotropy frame, and strain_rate_deviator is the
    /// pseudo-rate e = lambda 3/2 s of the local solve's stress s (eq. 3e, 3f),
    /// scaled so that sqrt(2/3 e : e) is the equivalent strain rate: the
    /// von Mises forms of the stress (2 mu e), the tangent and the
    /// stress-velocity linearisation then hold with 2 mu metric in place of
    /// 2 mu P_dev.
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
      // The non-quadratic law's lambda 3/2 (grad^2 g)^+ in Mandel's
      // notation (unset for von Mises and Hill48, whose tangent takes
      // P_dev), and the local Newton iterations it took.
      Mandel6x6    metric{};
      unsigned int local_iterations = 0;
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
      /// @p start: for a non-quadratic law, the point's metric at an earlier
      /// iterate (PointResponse::metric, the local compliance): its local
      /// solve starts from metric : e, first order in the change of the
      /// rate (or from von Mises's direction: nullptr).
      PointResponse evaluate(const SymmetricTensor<2, 3> &strain_rate,
                             const double                 strain_old,
                             const double                 dt,
                             const bool                   newton,
                             const Mandel6x6             &map,
                             const Mandel6x6 *start = nullptr) const;

      /// Either: Hill's with @p map, von Mises's without (nullptr).
      PointResponse evaluate(const SymmetricTensor<2, 3> &strain_rate,
                             const double                 strain_old,
                             const double                 dt,
                             const bool                   newton,
                             const Mandel6x6             *map,
                             const Mandel6x6             *start = nullptr) const
      {
        return map ? evaluate(strain_rate, strain_old, dt, newton, *map, start)
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

      /// The equivalent stress sigma_bar of a response in the sheet's
      /// criterion: the flow stress of the plastic law, scaled by rate/r_c
      /// in a rigid zone (eq. 3a), as sigma' : D = sigma_bar eps_bar_dot.
      static double equivalent_stress(const PointResponse &m)
      {
        return m.flow_stress;
      }

      /// Whether tangent() is 2 mu P_dev plus terms in D' and W only: the
      /// element then assembles it from products of the shape gradients
      /// (solver::CellTangent::add_deviatoric), the same matrix in 0.55-0.65
      /// of the time of the general 6x6 product (doc/theory.md, section 5a).
      bool isotropic() const { return iso; }

      /// The Hill coefficients (von Mises's when isotropic()).
      const Hill48 &hill() const { return coefficients; }
      /// Yld2004-18p or Hosford, or nothing (von Mises, Hill48).
      const Yld2004 *non_quadratic() const { return yld ? &*yld : nullptr; }
      /// "key = value" lines of the criterion's coefficients and its
      /// r-values and stress ratios (run summary).
      std::string criterion_summary() const;
      /// The criterion's (r0 + 2 r45 + r90)/4.
      double mean_r() const
      {
        return yld ? yld->mean_r() : coefficients.mean_r();
      }
      /// The local solves of the non-quadratic laws on this process.
      const DualStatistics &local_solves() const { return statistics; }
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
                            const double                 rate,
                            const double                 strain_old,
                            const double                 dt,
                            const bool                   newton) const;
      /// The non-quadratic law on a deviatoric rate in the orthotropy frame.
      PointResponse respond_dual(const SymmetricTensor<2, 3> &e,
                                 const double                 strain_old,
                                 const double                 dt,
                                 const bool                   newton,
                                 const Mandel6x6             *start) const;

      FlowStress             law;
      Hill48                 coefficients;
      std::optional<Yld2004> yld;
      Mandel6x6              root; // S in the orthotropy frame; I for yld
      mutable DualStatistics statistics;
      bool                   iso;
      double                 rolling;
      double                 cutoff; // limiting strain rate
      bool                   smooth;
      double                 bulk;
    };
  } // namespace material
} // namespace formsolve
