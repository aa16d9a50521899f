// A tool of Tools/Additional tools: any number besides punch, die and blank
// holder (a pad, a cushion, a second punch, a clamp), each with its side of
// the sheet, its shape and its own motion: fixed, prescribed along a
// direction, or under a set force along a direction.
#pragma once

#include <formsolve/parameters/force_curve.h>
#include <formsolve/parameters/tool.h>

#include <array>
#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    enum class ToolMotion
    {
      fixed,      // stays where it starts
      prescribed, // moves at Speed along Direction (until Stroke)
      force       // moves along Direction so that its force equals Force
    };

    struct AdditionalTool : Tool
    {
      bool                  above        = true; // Side: above or below
      bool                  solid_inside = true; // Solid: inside or outside
      ToolMotion            motion       = ToolMotion::fixed;
      std::array<double, 3> direction{{0, 0, -1}}; // unit, x y z
      double                speed  = 1;            // mm/s (prescribed)
      double                stroke = 0;            // mm; 0: the whole run
      ForceCurve            force;                 // N, full part (force)
      unsigned int          refinement_level = 0;

      /// The entries of subsection Tools/<name>, bound to these members.
      void declare(Declarations &d);
      /// @p axisymmetric, @p symmetric_x/y: the model's symmetries, which a
      /// direction must keep.
      void validate(const bool section,
                    const bool symmetric_x,
                    const bool symmetric_y) const;
    };

    /// The names of Tools/Additional tools in the input @p text (after the
    /// command line's @p overrides), to declare their subsections before
    /// the input is parsed; empty if the text does not parse (the real
    /// parse says why).
    std::vector<std::string> additional_tool_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides);
  } // namespace parameters
} // namespace formsolve
