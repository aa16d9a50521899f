#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/tools.h>

#include <cmath>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<HolderControl> control_names{{"gap", HolderControl::gap},
                                                {"force",
                                                 HolderControl::force}};
    } // namespace

    void Tools::declare(Declarations &d)
    {
      const Subsection s(d, "Tools");
      {
        const Subsection tool(d, "Punch");
        punch.declare(d);
        d.add("Stroke",
              punch_stroke,
              number("mm", 0),
              "Total punch travel (mm): the run ends here at the latest (see "
              "Time stepping/End of run).");
        d.add("Speed",
              punch_speed,
              number("mm/s", 0),
              "Punch speed (mm/s), moving in -z.");
      }
      {
        const Subsection tool(d, "Die");
        die.declare(d);
      }
      // The names are read ahead (additional_tool_names()), so that their
      // subsections are declared (declare_additional) when the input is.
      d.declare(
        "Additional tools",
        "",
        text("names, comma-separated"),
        "Names of more tools besides punch, die and blank holder (a pad, a "
        "cushion, a counter punch, a clamp), separated by commas; each has "
        "a subsection Tools/<name> with the entries of a tool and its side, "
        "solid and motion (see the subsection <name> below). Their history "
        "columns carry the name in lower case, spaces as underscores.",
        [](const std::string &) {});
      draw_beads.declare(d);
      const Subsection tool(d, "Blank holder");
      blank_holder.declare(d);
      d.add("Control",
            holder_control,
            control_names,
            "gap: the holder stays where 'Gap' puts it. force: the holder "
            "moves along z so that its contact force on the sheet equals "
            "'Force' in every step (solved with the velocities, "
            "doc/theory.md); it stops where it is once the blank rim has "
            "left it.");
      d.declare(
        "Force",
        "2671",
        text("a force in N (>= 0), a table 'travel:force, ...' (mm:N), or "
             "`siebel`"),
        "Blank-holder force for Control = force (N, > 0), for the full part "
        "(the model's share is taken by the symmetry factor): one number for "
        "the whole stroke, or a cushion curve 'travel:force, travel:force, "
        "...' of punch travel (mm, increasing from 0 or later) and force "
        "(N), linear in between and held at the end values beyond; or "
        "'siebel': Siebel's rule p = 0.0025 [(d0/d_p - 1)^2 + d_p/(200 "
        "t0)] R_m on the initial flange under the holder, with R_m = "
        "Material/Tensile strength (round blank, punch and holder; the value "
        "is printed). A force below 1/10 or above 10 times Siebel's gets a "
        "warning.",
        [this](const std::string &force) { read_holder_force(force); });
    }

    void Tools::read_holder_force(const std::string &force)
    {
      holder_force_by_siebel = force == "siebel";
      if (!holder_force_by_siebel)
        holder_force = ForceCurve::read(force, "Tools/Blank holder/Force");
    }

    void Tools::declare_additional(Declarations                   &d,
                                   const std::vector<std::string> &names)
    {
      const Subsection s(d, "Tools");
      additional.assign(names.size(), AdditionalTool{});
      for (std::size_t i = 0; i < names.size(); ++i)
        {
          AdditionalTool &t = additional[i];
          t.name            = names[i];
          t.shape           = ToolShape::flat;
          if (!name_problem(i).empty())
            continue; // refused by validate()
          const Subsection tool(d, t.name);
          t.declare(d);
        }
    }

    std::string Tools::name_problem(const std::size_t i) const
    {
      const std::string &n   = additional[i].name;
      const std::string  key = tool_key(n);
      if (key == "punch" || key == "die" || key == "blank_holder" ||
          n.find('/') != std::string::npos)
        return "`" + n +
               "` cannot name an additional tool (punch, die and blank "
               "holder have their own subsections; no '/')";
      for (std::size_t j = 0; j < i; ++j)
        if (tool_key(additional[j].name) == key)
          return "`" + n +
                 "` is named twice (names differing only in case or in "
                 "spaces and '_' are the same)";
      return "";
    }

    void Tools::validate() const
    {
      for (std::size_t i = 0; i < additional.size(); ++i)
        require(name_problem(i).empty(),
                "Tools/Additional tools",
                name_problem(i));
      punch.validate();
      die.validate();
      blank_holder.validate();
      require(punch.enabled, "Tools/Punch/Enabled", "the punch drives the run");
      require_positive(punch_speed, "Tools/Punch/Speed", "mm/s");
      require_positive(punch_stroke, "Tools/Punch/Stroke", "mm");
      if (blank_holder.enabled && holder_control == HolderControl::force)
        {
          for (const auto &point : holder_force.points)
            require_positive(point.second, "Tools/Blank holder/Force", "N");
          require(blank_holder.shape != ToolShape::flat,
                  "Tools/Blank holder/Control",
                  "force needs a holder with an opening (Shape round, "
                  "rounded rectangle or mesh), so that the blank can leave "
                  "it");
        }
    }
  } // namespace parameters
} // namespace formsolve
