#include <deal.II/base/utilities.h>

#include <formsolve/parameters/choice.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/tools.h>

#include <cmath>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    namespace
    {
      const Choice<HolderControl> control_names{{"gap", HolderControl::gap},
                                                {"force",
                                                 HolderControl::force}};
    } // namespace

    void Tools::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Tools");
      Tool p{"Punch"};
      Tool d{"Die", true, ToolShape::round, 42.5, 42.5, 42.5, 8, 8};
      Tool b{"Blank holder", true, ToolShape::round, 58.5, 0, 0, 0, 0};

      prm.enter_subsection("Punch");
      Tool::declare(prm, p);
      prm.declare_entry(
        "Stroke",
        "30",
        Double(0),
        "Total punch travel (mm): the run ends here at the latest (see "
        "Time stepping/End of run).");
      prm.declare_entry("Speed",
                        "1",
                        Double(0),
                        "Punch speed (mm/s), moving in -z.");
      prm.leave_subsection();

      prm.enter_subsection("Die");
      Tool::declare(prm, d);
      prm.leave_subsection();

      prm.enter_subsection("Blank holder");
      Tool::declare(prm, b);
      prm.declare_entry(
        "Control",
        "force",
        Selection(control_names.pattern()),
        "gap: the holder stays where 'Gap' puts it. force: the holder moves "
        "along z so that its contact force on the sheet equals 'Force' in "
        "every step (solved with the velocities, doc/theory.md); it stops "
        "where it is once the blank rim has left it.");
      prm.declare_entry(
        "Force",
        "2671",
        Anything(),
        "Blank-holder force for Control = force (N, >= 0), for the full "
        "part (the model's share is taken by the symmetry factor); or "
        "'siebel': Siebel's rule p = 0.0025 [(d0/d_p - 1)^2 + d_p/(200 t0)] "
        "R_m on the initial flange under the holder, with R_m = "
        "Material/Tensile strength (round blank, punch and holder; the value "
        "is printed). A force below 1/10 or above 10 times Siebel's gets a "
        "warning.");
      prm.leave_subsection();
      prm.declare_entry(
        "Additional tools",
        "",
        Anything(),
        "Names of more tools besides punch, die and blank holder (a pad, a "
        "cushion, a counter punch, a clamp), separated by commas; each has "
        "a subsection Tools/<name> with the entries of a tool and its side, "
        "solid and motion (see the subsection <name> below). Their history "
        "columns carry the name in lower case, spaces as underscores.");
      prm.leave_subsection();
    }

    void Tools::declare_additional(ParameterHandler               &prm,
                                   const std::vector<std::string> &names)
    {
      prm.enter_subsection("Tools");
      for (const auto &n : names)
        AdditionalTool::declare(prm, n);
      prm.leave_subsection();
    }

    void Tools::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Tools");
      prm.enter_subsection("Punch");
      punch.parse(prm);
      punch_stroke = prm.get_double("Stroke");
      punch_speed  = prm.get_double("Speed");
      prm.leave_subsection();
      prm.enter_subsection("Die");
      die.parse(prm);
      prm.leave_subsection();
      prm.enter_subsection("Blank holder");
      blank_holder.parse(prm);
      holder_control          = control_names.parse(prm.get("Control"));
      const std::string force = prm.get("Force");
      holder_force_by_siebel  = force == "siebel";
      if (!holder_force_by_siebel)
        {
          char *end    = nullptr;
          holder_force = std::strtod(force.c_str(), &end);
          require(end != force.c_str() && *end == '\0' &&
                    std::isfinite(holder_force) && holder_force >= 0,
                  "Tools/Blank holder/Force",
                  "`" + force +
                    "` is not accepted; it takes a force in N "
                    "(a number >= 0) or `siebel`");
        }
      prm.leave_subsection();
      additional.clear();
      for (const auto &n :
           dealii::Utilities::split_string_list(prm.get("Additional tools")))
        {
          const std::string key = tool_key(n);
          require(key != "punch" && key != "die" && key != "blank_holder" &&
                    n.find('/') == std::string::npos,
                  "Tools/Additional tools",
                  "`" + n +
                    "` cannot name an additional tool (punch, die and blank "
                    "holder have their own subsections; no '/')");
          for (const auto &a : additional)
            require(tool_key(a.name) != key,
                    "Tools/Additional tools",
                    "`" + n +
                      "` is named twice (names differing only in "
                      "case or in spaces and '_' are the same)");
          AdditionalTool t;
          t.name = n;
          prm.enter_subsection(n);
          t.parse(prm);
          prm.leave_subsection();
          additional.push_back(t);
        }
      prm.leave_subsection();
    }

    void Tools::validate() const
    {
      punch.validate();
      die.validate();
      blank_holder.validate();
      require(punch.enabled, "Tools/Punch/Enabled", "the punch drives the run");
      require_positive(punch_speed, "Tools/Punch/Speed", "mm/s");
      require_positive(punch_stroke, "Tools/Punch/Stroke", "mm");
      if (blank_holder.enabled && holder_control == HolderControl::force)
        {
          require_positive(holder_force, "Tools/Blank holder/Force", "N");
          require(blank_holder.shape != ToolShape::flat,
                  "Tools/Blank holder/Control",
                  "force needs a holder with an opening (Shape round, "
                  "rounded rectangle or mesh), so that the blank can leave "
                  "it");
        }
    }
  } // namespace parameters
} // namespace formsolve
