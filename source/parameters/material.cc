#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/flow_curve_file.h>
#include <formsolve/parameters/material.h>
#include <formsolve/parameters/number_pairs.h>
#include <formsolve/parameters/require.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<RigidZone> rigid_zone_names{{"smooth", RigidZone::smooth},
                                               {"piecewise",
                                                RigidZone::piecewise}};
      const Choice<FractureCriterion> fracture_names{
        {"oyane", FractureCriterion::oyane},
        {"cockcroft-latham", FractureCriterion::cockcroft_latham},
        {"none", FractureCriterion::none}};
      const Choice<FractureMeasure> measure_names{
        {"through-thickness average", FractureMeasure::through_thickness},
        {"local", FractureMeasure::local}};
      const Choice<FlowCurve> flow_curve_names{
        {"swift", FlowCurve::swift},
        {"voce", FlowCurve::voce},
        {"swift-voce", FlowCurve::swift_voce},
        {"hockett-sherby", FlowCurve::hockett_sherby},
        {"table", FlowCurve::table}};
      const Choice<FlowExtrapolation> extrapolation_names{
        {"power law", FlowExtrapolation::power_law},
        {"last slope", FlowExtrapolation::last_slope},
        {"constant", FlowExtrapolation::constant}};
      const Choice<MeanStress> mean_stress_names{
        {"cell pressure", MeanStress::cell_pressure},
        {"projected", MeanStress::projected}};
    } // namespace

    namespace
    {
      /// A number, or NaN for an empty entry; throws naming @p entry.
      double optional_number(const std::string &text, const std::string &entry)
      {
        if (text.find_first_not_of(" \t") == std::string::npos)
          return std::numeric_limits<double>::quiet_NaN();
        double x = 0;
        require(read_number(text, x),
                entry,
                "'" + text + "' is not a number (leave it empty if not given)");
        return x;
      }

      /// "minor:major, ..." -> pairs; throws naming the entry.
      std::vector<std::pair<double, double>> parse_table(const std::string &t)
      {
        const std::string entry  = "Material/Forming limit table";
        const auto        points = read_pairs(t, entry, "minor:major");
        for (const auto &[minor, major] : points)
          require(major > 0,
                  entry,
                  "'" + str(minor) + ":" + str(major) +
                    "' has no positive major strain");
        require(points.empty() || points.size() >= 2,
                entry,
                "needs at least two points");
        return points;
      }
    } // namespace

    /// The entries of the fracture criteria and the forming limit.
    void Material::declare_fracture(Declarations &d)
    {
      d.declare("Oyane a",
                "",
                text("a number, or empty: not given"),
                "a in Oyane's ductile-fracture integral I = (1/b) int "
                "(sigma_m / sigma_bar + a) d eps_bar (-); fracture where I "
                "reaches 1. A number, from this sheet's fracture strains; "
                "empty: not given (the integral is then not computed). "
                "Needed by Fracture criterion = oyane.",
                [this](const std::string &t) {
                  oyane_a = optional_number(t, "Material/Oyane a");
                });
      d.declare("Oyane b",
                "",
                text("a number > 0, or empty: not given"),
                "b in Oyane's integral (-), > 0; empty: not given. Needed "
                "by Fracture criterion = oyane.",
                [this](const std::string &t) {
                  oyane_b = optional_number(t, "Material/Oyane b");
                });
      d.add(
        "Cockcroft-Latham critical value",
        cockcroft_latham,
        number("MPa", 0),
        "C_crit (MPa) of the Cockcroft-Latham criterion C = int max(sigma_1, "
        "0) d eps_bar / C_crit; 0: not set (the integral itself is still "
        "written to the VTU files, so that C_crit can be calibrated).");
      d.add(
        "Fracture criterion",
        fracture,
        fracture_names,
        "The criterion that decides fracture: the punch travel at which it "
        "first reaches 1 anywhere is the critical stroke. oyane needs Oyane "
        "a and b, cockcroft-latham its critical value, both of this sheet; "
        "none: no ductile-fracture criterion (the forming limit curve and "
        "the neck still mark a split, Split/Measures).");
      d.add(
        "Fracture measure",
        fracture_measure,
        measure_names,
        "Where the criterion is read for the critical stroke. through-"
        "thickness average: the average through the thickness over each "
        "column of elements, as Oyane's constants are calibrated (from "
        "section-averaged fracture strains of tensile tests; a bent sheet's "
        "surface fibre carries bending strain no tensile test saw). local: "
        "the largest value at any point. Both are computed and reported "
        "every step (history.csv, run-summary.txt).");
      d.add("Fracture mean stress",
            mean_stress,
            mean_stress_names,
            "The mean stress sigma_m in Oyane's and Cockcroft-Latham's "
            "integrals. cell pressure: the penalty pressure of the element "
            "(constant per element, as the solver sees it; exact per layer in "
            "bending, where sigma_m jumps at the neutral axis). projected: the "
            "cell pressures averaged onto the nodes (lumped L2 projection) and "
            "interpolated, smooth across elements but smeared over the layer "
            "next to a jump (doc/theory.md, section 11b).");
      d.declare(
        "Forming limit table",
        "",
        text("minor:major pairs, comma-separated, or empty"),
        "The forming limit curve as 'minor:major, minor:major, ...' (true "
        "strains, minor increasing, at least two points; linear in between, "
        "constant beyond the ends). Empty: Keeler-Brazier from the hardening "
        "exponent and the sheet thickness (doc/theory.md, section 11).",
        [this](const std::string &t) { forming_limit_table = parse_table(t); });
      d.add("Safety margin",
            safety_margin,
            number("-", 0, 1),
            "Forming limit diagram: a point is at risk of crack when its major "
            "strain exceeds (1 - this) times the limit at its minor strain "
            "(-).");
      d.add("Severe thinning",
            severe_thinning,
            number("-", 0, 1),
            "Forming limit diagram: a point below the safety margin is in the "
            "severe-thinning zone when its thinning 1 - exp(-(major + minor)) "
            "exceeds this fraction of t0 (-).");
      d.add("Insufficient stretch",
            insufficient_stretch,
            number("-", 0, 1),
            "Forming limit diagram: a stretched point (major + minor >= 0) "
            "with a major true strain below this is insufficiently stretched "
            "(-).");
    }

    /// The flow curve's kind and Voce's constants.
    void Material::declare_flow_curve(Declarations &d)
    {
      d.add("Flow curve",
            flow_curve,
            flow_curve_names,
            "The strain hardening: swift, sigma = K (eps0 + eps)^n (Strength "
            "coefficient, Prestrain, Hardening exponent); voce, sigma = A - B "
            "exp(-C eps) (the Voce entries; Hardening exponent is then used "
            "only as the n-value of the Keeler-Brazier forming limit); "
            "swift-voce, alpha Swift + (1 - alpha) Voce with alpha = Swift "
            "weight (both curves' entries); hockett-sherby, sigma = A - B "
            "exp(-C eps^p) (the Voce entries and Hockett-Sherby exponent p; "
            "below eps = 1e-4 the chord from 0, where p < 1 makes the slope "
            "infinite); table, "
            "the points of Flow curve file, linear in between (Hardening "
            "exponent likewise only for the forming limit). Each times "
            "(rate/rate0)^m.");
      d.add("Flow curve file",
            flow_curve_file,
            input_file(),
            "Flow curve = table: a CSV of equivalent plastic strain (-) and "
            "flow stress (MPa), one point per line, strains from 0 up, "
            "stresses not falling (a header line and '#' lines are skipped); "
            "below its first strain the first stress.");
      d.add("Flow curve extrapolation",
            flow_extrapolation,
            extrapolation_names,
            "Flow curve = table, beyond its last point: power law, sigma_N "
            "(eps/eps_N)^n with n the last segment's slope in log-log (a Swift "
            "curve continued); last slope, the last segment's straight line; "
            "constant, sigma_N.");
      d.add("Voce saturation stress",
            voce_saturation,
            number("MPa"),
            "A in the Voce curve (MPa), the flow stress as the "
            "strain grows large.");
      d.add("Voce hardening amplitude",
            voce_amplitude,
            number("MPa"),
            "B in the Voce curve (MPa): A - B is the initial "
            "yield stress; 0 <= B < A.");
      d.add("Tensile strength",
            tensile_strength,
            number("MPa", 0),
            "R_m (MPa), the engineering tensile strength, for Siebel's "
            "blank-holder force (Tools/Blank holder/Force = siebel and its "
            "plausibility check); 0: from the flow curve at Considere's "
            "uniform strain, sigma(eps_u) exp(-eps_u).");
      d.add("Voce hardening rate",
            voce_rate,
            number("-"),
            "C in the Voce curve (-), >= 0.");
      d.add("Hockett-Sherby exponent",
            hockett_sherby_exponent,
            number("-", 0.05, 2),
            "p in the Hockett-Sherby curve sigma = A - B exp(-C eps^p) "
            "(-), with A, B, C the Voce entries; 1 is Voce's curve.");
      d.add("Swift weight",
            swift_weight,
            number("-", 0, 1),
            "alpha of Flow curve = swift-voce (-): the Swift curve's share, "
            "the Voce curve taking 1 - alpha.");
    }

    void Material::declare(Declarations &d)
    {
      const Subsection s(d, "Material");
      declare_flow_curve(d);
      d.add("Strength coefficient",
            strength_coefficient,
            number("MPa"),
            "K in the flow stress sigma = K (eps0 + eps)^n (rate/rate0)^m "
            "(MPa). Default: material B, type 430 stainless.");
      d.add("Hardening exponent",
            hardening_exponent,
            number("-", 0, 1),
            "Strain-hardening exponent n (-).");
      d.add("Prestrain",
            prestrain,
            number("-"),
            "eps0 (-): keeps the initial flow stress K eps0^n non-zero.");
      d.add("Rate sensitivity",
            rate_sensitivity,
            number("-", 0, 1),
            "Strain-rate sensitivity m (-); 0 gives a rigid-plastic law.");
      d.add("Reference strain rate",
            reference_strain_rate,
            number("1/s"),
            "rate0 in the flow stress law (1/s); also the scale of the "
            "volumetric penalty.");
      d.add("Limiting strain rate",
            limiting_strain_rate,
            number("1/s"),
            "The cutoff rate (1/s) below which the material behaves as a "
            "stiff linear viscous body (rigid zones); see Rigid zone.");
      d.add(
        "Rigid zone",
        rigid_zone,
        rigid_zone_names,
        "How the flow law meets the rigid zone, with r the equivalent "
        "strain rate and r_c the Limiting strain rate. smooth: the "
        "equivalent stress is s r/sqrt(r^2 + r_c^2), linear viscous well "
        "below r_c and the flow stress s well above it, with no kink "
        "(doc/theory.md eq. 3a). piecewise: linear viscous with the "
        "viscosity frozen at r_c below r_c, the flow stress above; the kink "
        "at r_c costs Newton iterations while points cross it (6-9 % more "
        "on the quarter cup, doc/convergence.md).");
      d.add("Volumetric penalty",
            volumetric_penalty,
            number("-"),
            "alpha (-): the mean stress is sigma_m = alpha K/rate0 "
            "tr(strain rate), integrated with reduced quadrature.");
      d.declare("Young's modulus",
                "",
                text("a number > 0 (MPa), or empty: not given"),
                "E (MPa), for springback only (Springback/Enabled): the "
                "forming itself is rigid-plastic. Empty: not given.",
                [this](const std::string &t) {
                  young_modulus =
                    optional_number(t, "Material/Young's modulus");
                });
      d.add("Poisson's ratio",
            poisson_ratio,
            number("-", 0, 0.4999),
            "nu (-), for springback only (with Young's modulus).");
      d.declare("Density",
                "",
                text("a number > 0 (kg/m^3), or empty: not given"),
                "rho (kg/m^3), for the mass of a trimmed part only (the "
                "forming is quasi-static). Empty: not given.",
                [this](const std::string &t) {
                  density = optional_number(t, "Material/Density");
                });
      anisotropy.declare(d);
      declare_fracture(d);
    }


    void Material::read_flow_curve()
    {
      if (flow_curve == FlowCurve::table)
        {
          require(!flow_curve_file.empty(),
                  "Material/Flow curve file",
                  "must name a CSV of strain, stress (MPa) when Flow curve = "
                  "table");
          flow_curve_points = parameters::read_flow_curve(flow_curve_file);
        }
    }

    void Material::validate() const
    {
      require(flow_curve != FlowCurve::table || flow_curve_points.size() >= 2,
              "Material/Flow curve file",
              "was not read (Flow curve = table)");
      require_positive(strength_coefficient,
                       "Material/Strength coefficient",
                       "MPa");
      if (has_voce())
        {
          require_positive(voce_saturation,
                           "Material/Voce saturation stress",
                           "MPa");
          require(std::isfinite(voce_amplitude) && voce_amplitude >= 0 &&
                    voce_amplitude < voce_saturation,
                  "Material/Voce hardening amplitude",
                  "must be in [0, Voce saturation stress) MPa, so that the "
                  "initial yield stress A - B is positive");
          require(std::isfinite(voce_rate) && voce_rate >= 0,
                  "Material/Voce hardening rate",
                  "must be >= 0");
        }
      require(std::isfinite(prestrain) &&
                (prestrain > 0 || hardening_exponent == 0),
              "Material/Prestrain",
              "must be positive when the hardening exponent is non-zero");
      require_positive(reference_strain_rate,
                       "Material/Reference strain rate",
                       "1/s");
      require_positive(limiting_strain_rate,
                       "Material/Limiting strain rate",
                       "1/s");
      require_positive(volumetric_penalty, "Material/Volumetric penalty", "");
      require(std::isnan(density) || density > 0,
              "Material/Density",
              "must be positive, got " + str(density));
      require(std::isnan(young_modulus) || young_modulus > 0,
              "Material/Young's modulus",
              "must be positive, got " + str(young_modulus));
      anisotropy.validate();
      require(std::isnan(oyane_b) || oyane_b > 0,
              "Material/Oyane b",
              "must be positive, got " + str(oyane_b));
      require(fracture != FractureCriterion::oyane || oyane_given(),
              std::isfinite(oyane_a) ? "Material/Oyane b" : "Material/Oyane a",
              "Fracture criterion = oyane needs Oyane's constants a and b of "
              "this sheet (from its fracture strains, doc/user-guide.md "
              "section 3.3); give both, or set Fracture criterion = none");
      require(fracture != FractureCriterion::cockcroft_latham ||
                cockcroft_latham > 0,
              "Material/Cockcroft-Latham critical value",
              "must be set (> 0 MPa) when it decides fracture");
      for (std::size_t k = 1; k < forming_limit_table.size(); ++k)
        require(forming_limit_table[k].first > forming_limit_table[k - 1].first,
                "Material/Forming limit table",
                "minor strains must increase");
    }
  } // namespace parameters
} // namespace formsolve
