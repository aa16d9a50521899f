// Subsection "Material": flow stress and the flow-formulation constants.
#pragma once

#include <formsolve/parameters/anisotropy.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class FractureCriterion
    {
      oyane,
      cockcroft_latham,
      none
    };

    /// Where a fracture criterion is read (doc/theory.md, section 11a).
    enum class FractureMeasure
    {
      through_thickness, // the average through the thickness per column
      local              // the largest quadrature-point value
    };

    /// The strain hardening of the flow stress (doc/theory.md, eq. 2).
    enum class FlowCurve
    {
      swift,          // K (eps0 + eps)^n
      voce,           // A - B exp(-C eps)
      swift_voce,     // alpha Swift + (1 - alpha) Voce
      hockett_sherby, // A - B exp(-C eps^p)
      table           // points of Flow curve file, linear in between
    };

    /// A tabulated flow curve beyond its last point.
    enum class FlowExtrapolation
    {
      power_law,  // sigma_N (eps/eps_N)^n_N, n_N of the last segment
      last_slope, // the last segment's straight line
      constant    // sigma_N
    };

    /// The mean stress in the fracture integrals (doc/theory.md, 11b).
    enum class MeanStress
    {
      cell_pressure, // the element's penalty pressure
      projected      // nodal averages of it, interpolated
    };

    /// The flow law below the limiting strain rate (rigid zones).
    enum class RigidZone
    {
      smooth,   // s rate/sqrt(rate^2 + cutoff^2): no kink at the cutoff
      piecewise // linear viscous below the cutoff, plastic above
    };

    struct Material
    {
      FlowCurve         flow_curve           = FlowCurve::swift;
      double            strength_coefficient = 829;   // K (MPa)
      double            hardening_exponent   = 0.2;   // n
      double            prestrain            = 0.002; // eps_0
      double            voce_saturation      = 0;     // A (MPa)
      double            voce_amplitude       = 0;     // B (MPa)
      double            voce_rate            = 0;     // C (-)
      double            swift_weight         = 0.5;   // alpha of swift-voce (-)
      double            hockett_sherby_exponent = 1;  // p (-)
      std::string       flow_curve_file; // Flow curve = table: CSV path
      FlowExtrapolation flow_extrapolation = FlowExtrapolation::power_law;
      /// Its (strain, stress MPa) points, read by read_flow_curve().
      std::vector<std::pair<double, double>> flow_curve_points;
      double    tensile_strength      = 0;    // R_m (MPa); 0: flow curve
      double    rate_sensitivity      = 0;    // m
      double    reference_strain_rate = 1;    // 1/s
      double    limiting_strain_rate  = 1e-4; // 1/s, rigid-zone cutoff
      RigidZone rigid_zone            = RigidZone::smooth;
      double    volumetric_penalty    = 1e4; // alpha (-)
      // Elasticity, for springback only (the forming is rigid-plastic):
      // NaN until given.
      double young_modulus = std::numeric_limits<double>::quiet_NaN(); // MPa
      double poisson_ratio = 0.3;                                      // (-)
      double density       = std::numeric_limits<double>::quiet_NaN(); // kg/m^3
      Anisotropy anisotropy; // yield criterion and its data

      // Ductile fracture: no criterion unless one is chosen with the
      // constants of this sheet (NaN: not given).
      double oyane_a          = std::numeric_limits<double>::quiet_NaN(); // (-)
      double oyane_b          = std::numeric_limits<double>::quiet_NaN(); // (-)
      double cockcroft_latham = 0; // C_crit (MPa), 0: not set
      FractureCriterion fracture         = FractureCriterion::none;
      FractureMeasure   fracture_measure = FractureMeasure::through_thickness;
      MeanStress        mean_stress      = MeanStress::cell_pressure;

      // Forming limit curve: Keeler-Brazier from n and t0 unless a table
      // (minor, major true strains, minor increasing) is given.
      std::vector<std::pair<double, double>> forming_limit_table;
      double                                 safety_margin = 0.1; // (-)
      // The other zones of the forming limit diagram.
      double severe_thinning      = 0.3;  // thinning fraction (-)
      double insufficient_stretch = 0.02; // major true strain (-)

      /// Whether Oyane's constants are given.
      bool oyane_given() const
      {
        return std::isfinite(oyane_a) && std::isfinite(oyane_b);
      }

      /// Whether Young's modulus is given (springback needs it).
      bool elastic_given() const { return std::isfinite(young_modulus); }

      /// The flow curve's stress scale (MPa): K, A for Voce, their blend,
      /// the largest tabulated stress.
      double stress_scale() const
      {
        return flow_curve == FlowCurve::voce ||
                   flow_curve == FlowCurve::hockett_sherby
                 ? voce_saturation
               : flow_curve == FlowCurve::swift_voce
                 ? swift_weight * strength_coefficient +
                     (1 - swift_weight) * voce_saturation
               : flow_curve == FlowCurve::table && !flow_curve_points.empty()
                 ? flow_curve_points.back().second
                 : strength_coefficient;
      }

      /// Whether the flow curve has Voce's part.
      bool has_voce() const
      {
        return flow_curve == FlowCurve::voce ||
               flow_curve == FlowCurve::swift_voce ||
               flow_curve == FlowCurve::hockett_sherby;
      }

      /// Flow curve = table: reads Flow curve file into flow_curve_points
      /// (after the input is read, before validate()).
      void read_flow_curve();

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;

    private:
      void declare_flow_curve(Declarations &d);
      void declare_fracture(Declarations &d);
    };
  } // namespace parameters
} // namespace formsolve
