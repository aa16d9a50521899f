// Each entry is declared once, bound to its member: the member's initial
// value is the default, reading the input (and --set) fills it, the tree
// the manual and the input check read has its default and what it accepts,
// and a value a pattern refuses is refused in words.
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/parameters.h>

#include "check.h"

#include <cmath>
#include <limits>

using namespace formsolve;

namespace
{
  const parameters::DeclaredEntry &entry(const parameters::Declarations &d,
                                         const std::string &section,
                                         const std::string &name)
  {
    return d.tree().sections.at(section).entries.at(name);
  }
} // namespace

int main()
{
  test::close("shortest exact text of 0.1",
              parameters::exact_text(0.1) == "0.1",
              1,
              0);
  test::close("exact text reads back",
              std::strtod(parameters::exact_text(1 / 3.).c_str(), nullptr),
              1 / 3.,
              0);

  dealii::ParameterHandler prm;
  parameters::Run          run;
  const parameters::Run    defaults;
  parameters::Declarations d(prm);
  run.declare(d);
  run.tools.declare_additional(d, {"Pad"});

  // Defaults come from the members, and the members keep them.
  test::close("default text from the member",
              entry(d, "Geometry", "Thickness").default_value == "0.78",
              1,
              0);
  test::close("member keeps its default",
              run.geometry.thickness,
              defaults.geometry.thickness,
              0);
  test::close("Oyane a not given by default",
              std::isnan(run.material.oyane_a),
              1,
              0);
  test::close("the die's own default diameter",
              run.tools.die.diameter,
              42.5,
              0);

  // The words come from the declaration.
  const auto &n = entry(d, "Material", "Hardening exponent");
  test::close("range in words",
              n.accepts.words == "a number from 0 to 1, dimensionless",
              1,
              0);
  test::close("the pattern refuses what the words exclude",
              n.accepts.pattern->match("2"),
              0,
              0);
  test::close("a file entry is marked",
              entry(d, "Geometry", "Mesh file").accepts.names_input_file,
              1,
              0);

  // Reading fills the bound members: numbers, choices, lists, custom
  // readers; an additional tool's subsection too.
  prm.parse_input_from_string("subsection Geometry\n"
                              "  set Thickness = 1.25\n"
                              "  set Model = quarter\n"
                              "end\n"
                              "subsection Material\n"
                              "  set Oyane a = 0.3\n"
                              "  set R-values = 1.5, 1.2, 1.8\n"
                              "  set Forming limit table = -0.2:0.5, 0:0.3\n"
                              "end\n"
                              "subsection Split\n"
                              "  set Measures = neck\n"
                              "end\n"
                              "subsection Tools\n"
                              "  subsection Blank holder\n"
                              "    set Force = siebel\n"
                              "  end\n"
                              "  subsection Pad\n"
                              "    set Direction = 1, 0, 0\n"
                              "  end\n"
                              "end\n");
  test::close("number read", run.geometry.thickness, 1.25, 0);
  test::close("choice read", run.geometry.model == model::Model::quarter, 1, 0);
  test::close("optional number read", run.material.oyane_a, 0.3, 0);
  test::close("list read",
              run.material.anisotropy.r_values.size() == 3 &&
                run.material.anisotropy.r_values[2] == 1.8,
              1,
              0);
  test::close("table read", run.material.forming_limit_table.size(), 2, 0);
  test::close("selection of measures read",
              !run.split.by_forming_limit && run.split.by_neck &&
                !run.split.by_fracture,
              1,
              0);
  test::close("word read", run.tools.holder_force_by_siebel, 1, 0);
  test::close("additional tool read",
              run.tools.additional.at(0).direction[0],
              1,
              0);
  test::close("additional tool's own default shape",
              run.tools.additional.at(0).shape == parameters::ToolShape::flat,
              1,
              0);

  // --set goes through the same reading.
  prm.enter_subsection("Mesh");
  prm.set("Layers through thickness", "6");
  prm.leave_subsection();
  test::close("set read", run.mesh.layers, 6, 0);

  // A custom reader refuses a bad value naming the entry.
  bool refused = false;
  try
    {
      prm.parse_input_from_string("subsection Tools\n"
                                  "  subsection Blank holder\n"
                                  "    set Force = lots\n"
                                  "  end\n"
                                  "end\n");
    }
  catch (const dealii::StandardExceptions::ExcMessage &e)
    {
      refused = std::string(e.what()).find("Tools/Blank holder/Force") !=
                std::string::npos;
    }
  test::close("custom reader names the entry", refused, 1, 0);
  return test::result();
}
