// Subsection "Material": flow stress and the flow-formulation constants.
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace formsolve
{
  namespace parameters
  {
    using dealii::ParameterHandler;

    struct Material
    {
      double strength_coefficient  = 829;   // K (MPa)
      double hardening_exponent    = 0.2;   // n
      double prestrain             = 0.002; // eps_0
      double rate_sensitivity      = 0;     // m
      double reference_strain_rate = 1;     // 1/s
      double limiting_strain_rate  = 1e-4;  // 1/s, rigid-zone cutoff
      double volumetric_penalty    = 1e4;   // alpha (-)

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };
  } // namespace parameters
} // namespace formsolve
