#include <formsolve/parameters/material.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    void Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry(
        "Strength coefficient",
        "829",
        Double(),
        "K in the flow stress sigma = K (eps0 + eps)^n (rate/rate0)^m "
        "(MPa). Default: material B, type 430 stainless.");
      prm.declare_entry("Hardening exponent",
                        "0.2",
                        Double(0, 1),
                        "Strain-hardening exponent n (-).");
      prm.declare_entry(
        "Prestrain",
        "0.002",
        Double(),
        "eps0 (-): keeps the initial flow stress K eps0^n non-zero.");
      prm.declare_entry(
        "Rate sensitivity",
        "0",
        Double(0, 1),
        "Strain-rate sensitivity m (-); 0 gives a rigid-plastic law.");
      prm.declare_entry(
        "Reference strain rate",
        "1",
        Double(),
        "rate0 in the flow stress law (1/s); also the scale of the "
        "volumetric penalty.");
      prm.declare_entry(
        "Limiting strain rate",
        "1e-4",
        Double(),
        "Below this equivalent strain rate (1/s) the material is "
        "treated as linear viscous (rigid zones): the effective "
        "viscosity is frozen at its value at this rate.");
      prm.declare_entry("Volumetric penalty",
                        "1e4",
                        Double(),
                        "alpha (-): the mean stress is sigma_m = alpha K/rate0 "
                        "tr(strain rate), integrated with reduced quadrature.");
      prm.leave_subsection();
    }

    void Material::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      strength_coefficient  = prm.get_double("Strength coefficient");
      hardening_exponent    = prm.get_double("Hardening exponent");
      prestrain             = prm.get_double("Prestrain");
      rate_sensitivity      = prm.get_double("Rate sensitivity");
      reference_strain_rate = prm.get_double("Reference strain rate");
      limiting_strain_rate  = prm.get_double("Limiting strain rate");
      volumetric_penalty    = prm.get_double("Volumetric penalty");
      prm.leave_subsection();
    }

    void Material::validate() const
    {
      require_positive(strength_coefficient,
                       "Material/Strength coefficient",
                       "MPa");
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
    }
  } // namespace parameters
} // namespace formsolve
