#include <deal.II/base/utilities.h>

#include <formsolve/model/model.h>
#include <formsolve/parameters/choice.h>
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/trimming.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const char *entry = "Trimming/Planes";

      const Choice<CurveSide> &curve_sides()
      {
        static const Choice<CurveSide> c{{"inside", CurveSide::inside},
                                         {"outside", CurveSide::outside},
                                         {"left", CurveSide::left},
                                         {"right", CurveSide::right}};
        return c;
      }

      /// "0.5 x - z" -> (x, 0.5), (z, -1); false if it is not such a sum.
      bool read_terms(const std::string                    &s,
                      std::vector<std::pair<char, double>> &terms)
      {
        std::size_t i    = 0;
        auto        skip = [&]() {
          while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
            ++i;
        };
        skip();
        while (i < s.size())
          {
            double sign = 1;
            if (s[i] == '+' || s[i] == '-')
              {
                sign = s[i] == '-' ? -1 : 1;
                ++i;
                skip();
              }
            else if (!terms.empty())
              return false; // two terms without a sign between them
            double      coefficient = 1;
            const char *start       = s.c_str() + i;
            char       *end         = nullptr;
            if (i < s.size() &&
                (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'))
              {
                coefficient = std::strtod(start, &end);
                i += end - start;
                skip();
                if (i < s.size() && s[i] == '*')
                  {
                    ++i;
                    skip();
                  }
              }
            if (i >= s.size() ||
                std::string("rxyz").find(s[i]) == std::string::npos)
              return false;
            terms.emplace_back(s[i], sign * coefficient);
            ++i;
            skip();
          }
        return !terms.empty();
      }
    } // namespace

    std::string name(const CurveSide side)
    {
      return curve_sides().name(side);
    }

    std::vector<PlaneCut> parse_plane_cuts(const std::string &text)
    {
      std::vector<PlaneCut> cuts;
      for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          const auto at = item.find_first_of("<>");
          PlaneCut   c;
          c.text  = item;
          bool ok = at != std::string::npos &&
                    item.find_first_of("<>", at + 1) == std::string::npos;
          char       *end  = nullptr;
          std::string rest = ok ? item.substr(at + 1) : "";
          if (ok && !rest.empty() && rest[0] == '=')
            rest = rest.substr(1);
          if (ok)
            {
              c.keep_greater = item[at] == '>';
              c.value        = std::strtod(rest.c_str(), &end);
              ok             = end != rest.c_str() &&
                   std::string(end).find_first_not_of(" \t") ==
                     std::string::npos &&
                   std::isfinite(c.value) &&
                   read_terms(item.substr(0, at), c.terms);
            }
          require(ok,
                  entry,
                  "'" + item +
                    "' is not a half-space 'a x + b y + c z < d' (or '>', "
                    "e.g. 'z > 8' or 'x + z < 30')");
          double norm = 0;
          for (const auto &t : c.terms)
            norm += t.second * t.second;
          require(norm > 0, entry, "'" + item + "' has no direction");
          cuts.push_back(c);
        }
      return cuts;
    }

    void Trimming::declare(Declarations &d)
    {
      const Subsection s(d, "Trimming");
      d.declare(
        "Planes",
        "",
        text("half-spaces 'a x + b y + c z < d' separated by ';', or empty"),
        "Half-spaces the trimmed part keeps, in the model's coordinates at "
        "the end of forming (mm; x, y, z in 3-D, r, z or x, z in the "
        "sections): 'z > 8; z < 20' keeps a ring of a cup's wall. The part "
        "kept is where every cut of this subsection keeps it. Empty with the "
        "other cuts empty: no trimming.",
        [this](const std::string &t) { planes = parse_plane_cuts(t); });
      d.add("Curve file",
            curve_file,
            input_file(),
            "A trim curve in plan view (3-D models): a CSV of x, y points "
            "(mm, the part's coordinates, one per line, in order), projected "
            "along z through the part. Closed when its last point repeats "
            "its first. Empty: none.");
      d.add("Curve keeps",
            curve_side,
            curve_sides(),
            "Which side of the curve stays: inside or outside a closed "
            "curve, left or right of an open one (walking from its first "
            "point, seen from +z).");
      d.add("Surface file",
            surface_file,
            input_file(),
            "A trim surface (3-D models): STL or a gmsh file, in the part's "
            "coordinates (mm). Empty: none.");
      d.add("Surface keeps",
            surface_side,
            Choice<SurfaceSide>{{"behind", SurfaceSide::behind},
                                {"in front", SurfaceSide::in_front}},
            "Which side of the surface stays: behind it (against its "
            "normals) or in front of it.");
      d.add("Tolerance",
            tolerance,
            number("mm", 0),
            "How far the cut edge may lie from the trim line (mm): cells "
            "the line crosses are refined until their nodes are this close "
            "to it; the part keeps the cells whose centres lie on its side.");
      d.add("Maximum refinement",
            max_passes,
            whole_number(0, 10),
            "Refinement passes along the trim line at most (each halves the "
            "cells it crosses); the run summary says how close the edge "
            "came if they do not reach Tolerance.");
    }

    void Trimming::validate() const
    {
      require(std::isfinite(tolerance) && tolerance > 0,
              "Trimming/Tolerance",
              "must be positive");
    }

    void check_trimming(const Run &run)
    {
      const auto &t = run.trimming;
      if (!t.any())
        return;
      const auto  names = model::coordinate_names(run.geometry.model);
      std::string letters;
      for (const auto &n : names)
        letters += n;
      for (const auto &c : t.planes)
        for (const auto &[letter, coefficient] : c.terms)
          require(letters.find(letter) != std::string::npos,
                  "Trimming/Planes",
                  "'" + c.text + "' names " + std::string(1, letter) +
                    ", not a coordinate of Geometry/Model = " +
                    model::name(run.geometry.model) + " (" + letters + ")");
      const bool three_d = model::space_dimension(run.geometry.model) == 3;
      require(three_d || t.curve_file.empty(),
              "Trimming/Curve file",
              "a curve in plan view needs a 3-D model (Geometry/Model = " +
                model::name(run.geometry.model) +
                "); a section is trimmed by Trimming/Planes");
      require(three_d || t.surface_file.empty(),
              "Trimming/Surface file",
              "a surface needs a 3-D model (Geometry/Model = " +
                model::name(run.geometry.model) +
                "); a section is trimmed by Trimming/Planes");
    }
  } // namespace parameters
} // namespace formsolve
