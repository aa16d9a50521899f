#include <deal.II/base/utilities.h>

#include <formsolve/parameters/anisotropy.h>
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<YieldCriterion> criterion_names{
        {"von Mises", YieldCriterion::von_mises},
        {"Hill48", YieldCriterion::hill48},
        {"Yld2004-18p", YieldCriterion::yld2004_18p},
        {"Hosford", YieldCriterion::hosford}};
      const Choice<HillCalibration> calibration_names{
        {"r-values", HillCalibration::r_values},
        {"yield stresses", HillCalibration::yield_stresses}};
      const Choice<YldCoefficients> yld_source_names{
        {"given", YldCoefficients::given},
        {"fitted", YldCoefficients::fitted}};
      const Choice<TransverseShear> shear_names{
        {"equal to N", TransverseShear::equal_to_n},
        {"isotropic", TransverseShear::isotropic}};
      const Choice<DamageNormalisation> normalisation_names{
        {"normal anisotropy", DamageNormalisation::normal_anisotropy},
        {"rolling direction", DamageNormalisation::rolling_direction}};

      std::string joined(const std::vector<double> &v)
      {
        std::ostringstream s;
        for (std::size_t i = 0; i < v.size(); ++i)
          s << (i ? ", " : "") << v[i];
        return s.str();
      }
    } // namespace

    bool Anisotropy::non_quadratic() const
    {
      return criterion == YieldCriterion::yld2004_18p ||
             criterion == YieldCriterion::hosford;
    }

    std::vector<double>
    Anisotropy::yld_coefficients(const unsigned int which) const
    {
      if (criterion == YieldCriterion::hosford)
        return std::vector<double>(9, 1.);
      std::vector<double> c = which == 1 ? yld_c1 : yld_c2;
      if (c.size() == 7)
        c.insert(c.begin() + 6, {1., 1.});
      return c;
    }

    bool Anisotropy::planar() const
    {
      if (criterion == YieldCriterion::yld2004_18p)
        {
          // Which coefficient sets leave the sheet plane isotropic has no
          // simple closed form: anything but Hosford's unit set counts.
          if (yld_source == YldCoefficients::fitted)
            return true;
          for (const unsigned int w : {1u, 2u})
            for (const double c : yld_coefficients(w))
              if (c != 1)
                return true;
          return false;
        }
      if (criterion != YieldCriterion::hill48)
        return false;
      // r0 = r45 = r90, or sigma45 = sigma90 = sigma0: isotropic in-plane.
      if (calibration == HillCalibration::r_values)
        return r_values.size() == 3 &&
               (r_values[1] != r_values[0] || r_values[2] != r_values[0]);
      return yield_stress_ratios.size() >= 2 &&
             (yield_stress_ratios[0] != 1 || yield_stress_ratios[1] != 1);
    }

    std::string Anisotropy::describe() const
    {
      if (criterion == YieldCriterion::von_mises)
        return "von Mises";
      if (criterion == YieldCriterion::hosford)
        return "Hosford, a = " + str(yield_exponent);
      if (criterion == YieldCriterion::yld2004_18p)
        return "Yld2004-18p, a = " + str(yield_exponent) +
               (yld_source == YldCoefficients::fitted
                  ? ", fitted to the data of Material/Yld2004-18p fit"
                  : ", C' = " + joined(yld_c1) + ", C'' = " + joined(yld_c2));
      if (calibration == HillCalibration::r_values)
        return "Hill48 from r-values " + joined(r_values);
      return "Hill48 from yield stress ratios " + joined(yield_stress_ratios) +
             (yield_stress_ratios.size() == 2 ? " (sigma_b/sigma0 = 1 assumed)"
                                              : "");
    }

    void Anisotropy::declare(Declarations &d)
    {
      d.add("Yield criterion",
            criterion,
            criterion_names,
            "von Mises; Hill's 1948 quadratic anisotropy; Barlat's "
            "Yld2004-18p (Yld2004-18p C1, C2, Yield exponent); or Hosford's "
            "isotropic non-quadratic criterion (Yield exponent; a = 6 suits "
            "BCC steels, 8 FCC aluminium). Each is normalised so that the "
            "flow stress is the rolling direction's uniaxial one: a flow "
            "curve from an RD tensile test is used as it is (doc/theory.md, "
            "sections 3a, 3b).");
      d.add("Yield exponent",
            yield_exponent,
            number("-", 2, 30),
            "The exponent a of Yld2004-18p and Hosford (-): 2 with unit "
            "coefficients is von Mises; 6 for BCC, 8 for FCC metals.");
      d.add("Yld2004-18p C1",
            yld_c1,
            numbers("-", 7, 9),
            "The coefficients of Yld2004-18p's first linear transformation "
            "C' (-), in the order c12, c13, c21, c23, c31, c32, c66 (seven: "
            "c44 = c55 = 1, the out-of-plane shears that in-plane tests do "
            "not identify) or c12, c13, c21, c23, c31, c32, c44, c55, c66 "
            "(nine); indices 1 = RD, 2 = TD, 3 = ND. All ones with the "
            "same C2 is Hosford's criterion.");
      d.add("Yld2004-18p C2",
            yld_c2,
            numbers("-", 7, 9),
            "The coefficients of the second linear transformation C'' (-), "
            "in the order of Yld2004-18p C1.");
      d.add("Yld2004-18p coefficients",
            yld_source,
            yld_source_names,
            "given: Yld2004-18p C1, C2 as entered. fitted: c12, c13, c21, "
            "c23, c31, c32 and c66 of both are fitted by least squares to "
            "the data of subsection Yld2004-18p fit, starting from C1, C2 "
            "(c44, c55 stay as given); the run summary prints the fitted "
            "coefficients, the fit next to the data and the RMS errors "
            "(doc/theory.md eq. 3g).");
      fit.declare(d);
      d.add(
        "Hill calibration",
        calibration,
        calibration_names,
        "How Hill48's coefficients are found: from the R-values, or from the "
        "Yield stress ratios. Hill48 cannot match both for most alloys; the "
        "run summary prints F, G, H, L, M, N and the r-values and stress "
        "ratios at 0, 45 and 90 degrees that follow.");
      d.add(
        "R-values",
        r_values,
        numbers("-", 1, 3),
        "Lankford coefficients (width over thickness strain of a tensile "
        "test, -): one normal r, or r0, r45, r90 (0, 45, 90 degrees to the "
        "rolling direction). Planar data (not all equal) need a 3-D model.");
      d.add("Yield stress ratios",
            yield_stress_ratios,
            numbers("-", 0, 3),
            "sigma45/sigma0, sigma90/sigma0 and optionally sigma_b/sigma0 "
            "(uniaxial flow stresses at 45 and 90 degrees to the rolling "
            "direction and the balanced-biaxial one, over the RD flow stress, "
            "-); without sigma_b/sigma0 it is taken as 1 (balanced biaxial, "
            "equivalently through-thickness, as strong as RD), and the summary "
            "says so. For Hill calibration = yield stresses.");
      d.add(
        "Transverse shear",
        transverse_shear,
        shear_names,
        "Hill's L and M (shear in the planes through the normal), which "
        "in-plane tests do not fix: equal to N (the common choice; transverse "
        "isotropy about the normal either way) or isotropic (3/2, von "
        "Mises's). They matter only where the sheet is sheared through its "
        "thickness, over tool radii.");
      d.add("Rolling direction",
            rolling_direction,
            number("degrees", -360, 360),
            "Angle of the rolling direction from the x axis in "
            "the sheet plane (degrees): 3-D models and plane strain (0: RD "
            "across the tools, along the section; 90: the section along TD); "
            "the axisymmetric model takes normal anisotropy only, where it "
            "has no effect.");
      d.add("Fracture constants normalisation",
            damage_normalisation,
            normalisation_names,
            "The equivalent stress and strain Oyane a, b and the Cockcroft-"
            "Latham critical value were calibrated in. normal anisotropy: "
            "Hill's sigma_bar^2 = 3/(2(2+r)) [r(s1-s2)^2 + (s2-s3)^2 + "
            "(s3-s1)^2] (the reference materials' constants), converted to "
            "formsolve's with k = sqrt(2(2+r)/(3(1+r))): a/k, b/k^2, C/k "
            "(r the mean r-value; no change for von Mises). rolling direction: "
            "formsolve's own (G + H = 1), used as given.");
    }


    void Anisotropy::validate() const
    {
      require(r_values.size() == 1 || r_values.size() == 3,
              "Material/R-values",
              "needs one normal r or three values r0, r45, r90, got " +
                std::to_string(r_values.size()));
      for (const double r : r_values)
        require_positive(r, "Material/R-values", "-");
      if (criterion == YieldCriterion::hill48 &&
          calibration == HillCalibration::yield_stresses)
        {
          require(yield_stress_ratios.size() >= 2,
                  "Material/Yield stress ratios",
                  "needs sigma45/sigma0 and sigma90/sigma0 (and optionally "
                  "sigma_b/sigma0) for Hill calibration = yield stresses");
          for (const double s : yield_stress_ratios)
            require_positive(s, "Material/Yield stress ratios", "-");
          // F, G, H, N > 0 bounds a convex criterion that Hill48 with these
          // ratios gives (theory.md, section 3a).
          const auto  &v  = yield_stress_ratios;
          const double b  = v.size() > 2 ? v[2] : 1.;
          const double s9 = 1 / (v[1] * v[1]), sb = 1 / (b * b);
          const double F = (s9 + sb - 1) / 2, G = (1 + sb - s9) / 2,
                       H = (1 + s9 - sb) / 2;
          const double N = 2 / (v[0] * v[0]) - (F + G) / 2;
          require(F > 0 && G > 0 && H > 0 && N > 0 && F * G + G * H + H * F > 0,
                  "Material/Yield stress ratios",
                  "give no convex Hill48 criterion (F = " + str(F) +
                    ", G = " + str(G) + ", H = " + str(H) + ", N = " + str(N) +
                    "); check the ratios");
        }
      if (criterion == YieldCriterion::yld2004_18p &&
          yld_source == YldCoefficients::fitted)
        fit.validate(14);
      for (const auto *c : {&yld_c1, &yld_c2})
        require(c->size() == 7 || c->size() == 9,
                c == &yld_c1 ? "Material/Yld2004-18p C1"
                             : "Material/Yld2004-18p C2",
                "needs 7 numbers (c12, c13, c21, c23, c31, c32, c66) or 9 "
                "(c12, c13, c21, c23, c31, c32, c44, c55, c66), got " +
                  std::to_string(c->size()));
      require(std::isfinite(rolling_direction),
              "Material/Rolling direction",
              "must be finite");
    }
  } // namespace parameters
} // namespace formsolve
