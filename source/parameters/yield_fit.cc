#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/yield_fit.h>

#include <cmath>

namespace formsolve
{
  namespace parameters
  {
    unsigned int YieldFit::size() const
    {
      // sigma_0/sigma_0 = 1 holds for any coefficients: it fixes nothing.
      unsigned int n = 0;
      for (std::size_t i = 0; i < stress_ratios.size(); ++i)
        n += (angles[i] != 0);
      return n + r_values.size() + biaxial_stress_ratio.size() +
             biaxial_r_value.size() + plane_strain_ratio.size();
    }

    void YieldFit::declare(Declarations &d)
    {
      const Subsection s(d, "Yld2004-18p fit");
      d.add("Angles",
            angles,
            numbers("degrees", 1, 0, 0),
            "The angles to the rolling direction (degrees, 0 to 90) of the "
            "tensile tests whose Stress ratios and R-values follow, in the "
            "same order.");
      d.add("Stress ratios",
            stress_ratios,
            numbers("-", 0, 0, 0),
            "sigma_theta/sigma_0 (-): the uniaxial flow stress at each of "
            "Angles over the rolling direction's (at the same plastic work); "
            "empty: not given.");
      d.add("R-values",
            r_values,
            numbers("-", 0, 0, 0),
            "r_theta (-): width over thickness strain rate of the tensile "
            "test at each of Angles; empty: not given.");
      d.add("Biaxial stress ratio",
            biaxial_stress_ratio,
            numbers("-", 0, 1, 0),
            "sigma_b/sigma_0 (-): balanced-biaxial flow stress (bulge test) "
            "over the rolling direction's; empty: not given.");
      d.add("Biaxial r-value",
            biaxial_r_value,
            numbers("-", 0, 1, 0),
            "r_b (-): TD over RD strain rate in balanced-biaxial tension (disc "
            "compression); empty: not given.");
      d.add("Plane strain ratio",
            plane_strain_ratio,
            numbers("-", 0, 1, 0),
            "sigma_ps/sigma_0 (-): the RD stress of plane-strain tension "
            "along RD (no TD strain) over the RD uniaxial flow stress; empty: "
            "not given.");
      d.add("Starts",
            starts,
            whole_number(1, 100000),
            "Starting points of the least-squares search: Yld2004-18p C1, "
            "C2 and pseudo-random perturbations of them (the same on every "
            "run and rank). The sum of squares has many local minima; more "
            "starts find lower ones, at about 16 ms each.");
    }

    void YieldFit::validate(const unsigned int unknowns) const
    {
      const std::string at = "Material/Yld2004-18p fit/";
      for (const double a : angles)
        require(a >= 0 && a <= 90,
                at + "Angles",
                "must lie in 0 to 90 degrees, got " + str(a));
      for (const auto &[name, v] :
           {std::pair<std::string, const std::vector<double> *>{"Stress ratios",
                                                                &stress_ratios},
            {"R-values", &r_values}})
        {
          require(v->empty() || v->size() == angles.size(),
                  at + name,
                  "needs one value per angle of " + at + "Angles (" +
                    std::to_string(angles.size()) + "), got " +
                    std::to_string(v->size()));
          for (const double x : *v)
            require_positive(x, at + name, "-");
        }
      for (const auto *v :
           {&biaxial_stress_ratio, &biaxial_r_value, &plane_strain_ratio})
        for (const double x : *v)
          require_positive(x,
                           at + (v == &biaxial_stress_ratio
                                   ? "Biaxial stress ratio"
                                 : v == &biaxial_r_value
                                   ? "Biaxial r-value"
                                   : "Plane strain ratio"),
                           "-");
      require(size() >= unknowns,
              at + "Stress ratios",
              "the fit of Yld2004-18p's " + std::to_string(unknowns) +
                " coefficients needs at least as many data, got " +
                std::to_string(size()) +
                " (stress ratios away from 0 degrees, r-values, the biaxial "
                "and plane-strain points); with fewer, give the coefficients "
                "(Material/Yld2004-18p coefficients = given) or use Hill48");
    }
  } // namespace parameters
} // namespace formsolve
