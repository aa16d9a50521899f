#include <deal.II/base/utilities.h>

#include <formsolve/parameters/additional_tool.h>
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/listed_names.h>
#include <formsolve/parameters/require.h>

#include <cmath>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<ToolMotion> motion_names{{"fixed", ToolMotion::fixed},
                                            {"prescribed",
                                             ToolMotion::prescribed},
                                            {"force", ToolMotion::force}};
      const Choice<bool>       side_names{{"above", true}, {"below", false}};
      const Choice<bool> solid_names{{"inside", true}, {"outside", false}};
    } // namespace

    void AdditionalTool::declare(Declarations &d)
    {
      Tool::declare(d);
      d.add("Side",
            above,
            side_names,
            "The side of the sheet the tool works on: above (its face at z = "
            "thickness + Gap) or below (at z = -Gap).");
      d.add("Solid",
            solid_inside,
            solid_names,
            "Round and rounded rectangle: the tool's solid lies inside its "
            "outline (a punch, a pad) or outside it (a ring around an "
            "opening, as the die and the blank holder); the Profile radius "
            "rounds the outline's edge.");
      d.add(
        "Motion",
        motion,
        motion_names,
        "fixed: the tool stays where it starts. prescribed: it moves at "
        "Speed along Direction, for the whole run or until it has "
        "travelled Stroke. force: it moves along Direction so that the "
        "force it exerts on the sheet along Direction equals Force in every "
        "step (solved with the velocities, as the blank holder's).");
      d.add("Direction",
            direction,
            numbers("-", 3, 3),
            "x, y, z of the direction of motion (prescribed) or of the force "
            "on the sheet (force); made unit length. An axisymmetric model "
            "takes only z; a symmetry plane, no component normal to it.");
      d.add("Speed",
            speed,
            number("mm/s", 0),
            "Motion = prescribed: speed along Direction (mm/s).");
      d.add("Stroke",
            stroke,
            number("mm", 0),
            "Motion = prescribed: the tool stops after this "
            "travel (mm), landing on it exactly; 0: it moves "
            "for the whole run.");
      d.declare("Force",
                "0",
                text("a force in N, or a table 'travel:force, ...' (mm:N)"),
                "Motion = force: the force the tool exerts on the sheet "
                "along Direction (N, > 0), for the full part (the model's "
                "share is taken by the symmetry factor); one number, or a "
                "table 'travel:force, ...' over the punch travel (mm), as "
                "Tools/Blank holder/Force: a holder segment with its own "
                "cushion curve.",
                [this](const std::string &t) {
                  force = ForceCurve::read(t, "Tools/" + name + "/Force");
                });
      d.add("Refinement level",
            refinement_level,
            whole_number(0, 10),
            "Extra refinement levels of the sheet near the "
            "tool's radii, as Mesh refinement/Punch level for "
            "the punch (0: none).");
    }


    void AdditionalTool::validate(const bool section,
                                  const bool symmetric_x,
                                  const bool symmetric_y) const
    {
      if (!enabled)
        return;
      Tool::validate();
      const std::string e = "Tools/" + name + "/";
      if (motion == ToolMotion::fixed)
        return;
      const double length =
        std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                  direction[2] * direction[2]);
      require(std::isfinite(length) && length > 0,
              e + "Direction",
              "must not be zero");
      require(!section || (direction[0] == 0 && direction[1] == 0),
              e + "Direction",
              "must lie along z for a 2-D Geometry/Model (axisymmetric, "
              "plane strain)");
      require((!symmetric_x || direction[0] == 0) &&
                (!symmetric_y || direction[1] == 0),
              e + "Direction",
              "must lie in the model's symmetry planes (no x component "
              "with a plane x = 0, no y component with y = 0)");
      if (motion == ToolMotion::prescribed)
        require_positive(speed, e + "Speed", "mm/s");
      else
        for (const auto &point : force.points)
          require_positive(point.second, e + "Force", "N");
    }

    std::vector<std::string> additional_tool_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      return listed_names(text, overrides, "Tools/Additional tools");
    }
  } // namespace parameters
} // namespace formsolve
