#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/draw_beads.h>
#include <formsolve/parameters/listed_names.h>
#include <formsolve/parameters/number_pairs.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/tool.h>

#include <cmath>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<BeadModel> model_names{{"forces", BeadModel::forces},
                                          {"geometry", BeadModel::geometry}};

      /// "x:y, x:y, ..." (3-D) or one number x (2-D sections).
      std::vector<std::pair<double, double>> read_line(const std::string &t,
                                                       const std::string &e)
      {
        if (t.find_first_not_of(" \t") == std::string::npos)
          return {}; // not given: validate() says so
        if (t.find(':') != std::string::npos)
          return read_pairs(t, e, "x:y");
        double x = 0;
        require(read_number(t, x),
                e,
                "`" + t +
                  "` is not accepted; it takes points 'x:y, x:y, ...' (mm) "
                  "in plan view, or in a 2-D model the bead's x (mm)");
        return {{x, 0.}};
      }
    } // namespace

    void DrawBead::declare(Declarations &d)
    {
      const std::string where = "Tools/Draw beads/" + name + "/Line";
      d.declare(
        "Line",
        line_text,
        text("points 'x:y, x:y, ...' in mm (3-D), or one x in mm (2-D)"),
        "Where the bead lies on the die/holder face, in plan view (mm, the "
        "part's coordinates, as the tools'): a polyline 'x:y, x:y, ...' of "
        "two or more points in a 3-D model; in a 2-D model one number, the "
        "radius of a round bead (axisymmetric) or the x of a straight bead "
        "across the strip (plane strain). The bead acts where sheet "
        "material lies across the line.",
        [this, where](const std::string &t) {
          line_text = t;
          line      = read_line(t, where);
        });
      d.add("Closed",
            closed,
            "3-D: the line runs on from its last point back to the first (a "
            "bead around the part).");
      d.add("Model",
            model,
            model_names,
            "forces: the bead's Restraining force and Opening force per unit "
            "length as given (a drawbead test, a supplier's table). "
            "geometry: both computed from Height, Bead radius, Shoulder "
            "radius and Friction coefficient by bending and unbending over "
            "the bead and its shoulders with friction in between "
            "(doc/theory.md, section 6d), with the sheet's thickness and "
            "flow stress.");
      d.add("Restraining force",
            restraining,
            numbers("N/mm", 1, 2, 0),
            "Model = forces: the force per unit length of bead that opposes "
            "material crossing the line (N/mm, >= 0), at full penetration; "
            "two numbers: at the line's start and end, linear in between.");
      d.add("Opening force",
            opening,
            numbers("N/mm", 1, 2, 0),
            "Model = forces: the force per unit length that pushes die and "
            "holder apart (N/mm, >= 0) at full penetration; it is taken "
            "from the blank holder's force (Control = force), so that the "
            "holder presses the flange with the rest. Two numbers: start "
            "and end of the line.");
      d.add("Height",
            height,
            number("mm", 0),
            "Height of the bead (mm, > 0): the bead's force grows with its "
            "penetration p = Height - c, c the clearance between the tools "
            "and the sheet at the line (0 with the holder closed): in "
            "proportion p/Height for Model = forces, through the wrap angle "
            "for Model = geometry.");
      d.add("Bead radius",
            bead_radius,
            number("mm", 0),
            "Model = geometry: radius of the round bead (mm, > 0).");
      d.add("Shoulder radius",
            shoulder_radius,
            number("mm", 0),
            "Model = geometry: radius of the groove's two shoulders (mm, > "
            "0).");
      d.add("Friction coefficient",
            friction,
            number("-", 0),
            "Model = geometry: Coulomb friction between sheet, bead and "
            "shoulders (-).");
    }

    void DrawBead::validate(const bool section) const
    {
      const std::string e = "Tools/Draw beads/" + name + "/";
      require(!line.empty(),
              e + "Line",
              "must be given: where the bead lies (each bead named in "
              "Tools/Draw beads/Names needs its subsection with a Line)");
      require(section ? line.size() == 1 : line.size() >= 2,
              e + "Line",
              section ? "takes one number, the bead's x (mm), in a 2-D model"
                      : "takes two or more points 'x:y, x:y, ...' in a 3-D "
                        "model");
      require(section || length() > 0,
              e + "Line",
              "has no length (its points coincide)");
      require(!section || line[0].first > 0,
              e + "Line",
              "must be > 0 (a bead at x = 0 lies on the axis or the "
              "symmetry plane)");
      require_positive(height, e + "Height", "mm");
      for (const double f : restraining)
        require(f >= 0, e + "Restraining force", "must be >= 0 N/mm");
      for (const double f : opening)
        require(f >= 0, e + "Opening force", "must be >= 0 N/mm");
      if (model != BeadModel::geometry)
        return;
      require_positive(bead_radius, e + "Bead radius", "mm");
      require_positive(shoulder_radius, e + "Shoulder radius", "mm");
      require(height < bead_radius + shoulder_radius,
              e + "Height",
              "(" + str(height) +
                " mm) must stay below Bead radius + Shoulder radius (" +
                str(bead_radius + shoulder_radius) +
                " mm): deeper, the sheet would wrap more than 90 degrees "
                "round the bead, which the bead model cannot hold");
    }

    double DrawBead::length() const
    {
      double l = 0;
      for (std::size_t i = 0; i + 1 < line.size() + (closed ? 1 : 0); ++i)
        {
          const auto &a = line[i], &b = line[(i + 1) % line.size()];
          l += std::hypot(b.first - a.first, b.second - a.second);
        }
      return l;
    }

    std::string DrawBead::key() const
    {
      return "bead_" + tool_key(name);
    }

    void DrawBeads::declare(Declarations &d)
    {
      const Subsection s(d, "Draw beads");
      d.declare("Names",
                "",
                text("names, comma-separated"),
                "Names of the equivalent draw beads, separated by commas; "
                "each has a subsection Tools/Draw beads/<name> with its line "
                "and forces (see <name> below). history.csv carries "
                "bead_<name>_force (N, restraining, full part), _opening (N), "
                "_work (N mm) and _drawn (mm of material drawn across).",
                [](const std::string &) {});
    }

    void DrawBeads::declare_beads(Declarations                   &d,
                                  const std::vector<std::string> &names)
    {
      const Subsection tools(d, "Tools");
      const Subsection s(d, "Draw beads");
      beads.assign(names.size(), DrawBead{});
      for (std::size_t i = 0; i < names.size(); ++i)
        {
          beads[i].name = names[i];
          if (names[i].find('/') != std::string::npos)
            continue; // refused by validate()
          const Subsection bead(d, names[i]);
          beads[i].declare(d);
        }
    }

    void DrawBeads::validate(const bool section) const
    {
      for (std::size_t i = 0; i < beads.size(); ++i)
        {
          require(beads[i].name.find('/') == std::string::npos,
                  "Tools/Draw beads/Names",
                  "`" + beads[i].name + "` cannot name a bead (no '/')");
          for (std::size_t j = 0; j < i; ++j)
            require(beads[i].key() != beads[j].key(),
                    "Tools/Draw beads/Names",
                    "`" + beads[i].name + "` is named twice");
          beads[i].validate(section);
        }
    }

    std::vector<std::string> draw_bead_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      return listed_names(text, overrides, "Tools/Draw beads/Names");
    }
  } // namespace parameters
} // namespace formsolve
