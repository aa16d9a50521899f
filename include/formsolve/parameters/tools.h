// Subsection "Tools": punch, die and blank holder; the punch motion and the
// blank-holder control; the tools of Additional tools.
#pragma once

#include <formsolve/parameters/additional_tool.h>
#include <formsolve/parameters/tool.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    enum class HolderControl
    {
      gap,  // held at its initial position
      force // moves so that its contact force equals Force
    };

    struct Tools
    {
      Tool punch{"Punch"}, die{"Die"}, blank_holder{"Blank holder"};

      double punch_stroke = 30; // mm, total punch travel (bound of the run)
      double punch_speed  = 1;  // mm/s, in -z

      HolderControl holder_control         = HolderControl::force;
      double        holder_force           = 2671;  // N, full part
      bool          holder_force_by_siebel = false; // Force = siebel

      std::vector<AdditionalTool> additional;

      static void declare(ParameterHandler &prm);
      /// The subsections Tools/<name> of the additional tools @p names
      /// (read from the input by additional_tool_names()).
      static void declare_additional(ParameterHandler               &prm,
                                     const std::vector<std::string> &names);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };
  } // namespace parameters
} // namespace formsolve
