// Subsection "Tools": punch, die and blank holder; the punch motion and the
// blank-holder control; the tools of Additional tools.
#pragma once

#include <formsolve/parameters/additional_tool.h>
#include <formsolve/parameters/draw_beads.h>
#include <formsolve/parameters/force_curve.h>
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
      Tool punch{"Punch"};
      Tool die{"Die", true, ToolShape::round, 42.5, 42.5, 42.5, 8, 8};
      Tool
        blank_holder{"Blank holder", true, ToolShape::round, 58.5, 0, 0, 0, 0};

      double punch_stroke = 30; // mm, total punch travel (bound of the run)
      double punch_speed  = 1;  // mm/s, in -z

      HolderControl holder_control = HolderControl::force;
      ForceCurve    holder_force   = ForceCurve::constant(2671); // N, full part
      bool          holder_force_by_siebel = false; // Force = siebel

      std::vector<AdditionalTool> additional;
      DrawBeads                   draw_beads;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      /// The entry Tools/Additional tools and the subsections Tools/<name>
      /// of the additional tools @p names (read from the input ahead by
      /// additional_tool_names()).
      void declare_additional(Declarations                   &d,
                              const std::vector<std::string> &names);
      void validate() const;

    private:
      void read_holder_force(const std::string &force);
      /// Why additional tool @p i cannot have its name; empty if it can.
      std::string name_problem(const std::size_t i) const;
    };
  } // namespace parameters
} // namespace formsolve
