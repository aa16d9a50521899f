#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/springback.h>

#include <cmath>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      /// "x, y, z" -> numbers, or empty if one is not a number.
      std::vector<double> coordinates(const std::string &text)
      {
        std::vector<double> out;
        for (const auto &x : dealii::Utilities::split_string_list(text, ','))
          {
            char        *end = nullptr;
            const double v   = std::strtod(x.c_str(), &end);
            if (end == x.c_str() || *end != '\0' || !std::isfinite(v))
              return {};
            out.push_back(v);
          }
        return out;
      }
    } // namespace

    std::vector<std::vector<double>> parse_points(const std::string &text)
    {
      std::vector<std::vector<double>> points;
      for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
        if (!item.empty())
          {
            points.push_back(coordinates(item));
            require(!points.back().empty(),
                    "Springback/Measure points",
                    "'" + item + "' is not a point 'x, y, z' (or 'x, z')");
          }
      return points;
    }

    std::vector<SupportPoint> parse_supports(const std::string &text)
    {
      std::vector<SupportPoint> points;
      for (const auto &item : dealii::Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          const auto   colon = item.find(':');
          SupportPoint s;
          bool         ok = colon != std::string::npos;
          if (ok)
            {
              s.coordinates = coordinates(item.substr(0, colon));
              ok            = !s.coordinates.empty();
              s.components  = dealii::Utilities::trim(item.substr(colon + 1));
              ok            = ok && !s.components.empty() &&
                   s.components.find_first_not_of("rxyz") == std::string::npos;
            }
          require(ok,
                  "Springback/Supports",
                  "'" + item +
                    "' is not 'coordinates: components' (e.g. '0, 0, 10: "
                    "z' or '35, 0: xz')");
          points.push_back(s);
        }
      return points;
    }

    void Springback::declare(Declarations &d)
    {
      const Subsection s(d, "Springback");
      d.add("Enabled",
            enabled,
            "After the last step, take the tools away and release the "
            "end-of-forming stresses elastically on the deformed mesh (with "
            "an elasto-plastic correction where the released stress "
            "reverses the yield), and write the sprung part "
            "(springback.pvtu) and its measures. Needs Material/Young's "
            "modulus.");
      d.add("Element degree",
            degree,
            whole_number(0, 3),
            "Polynomial degree of the release's displacement on the forming "
            "mesh; 0: the forming's (Mesh/Element degree), whose equilibrium "
            "the end stress satisfies exactly. A higher degree than the "
            "forming's avoids the shear locking of coarse trilinear elements "
            "in bending, but takes the tools' forces as a load density "
            "(doc/theory.md, section 12; doc/springback.md compares them).");
      d.declare(
        "Supports",
        "",
        text("'coordinates: components' items separated by ';', or empty"),
        "How the part is held while it springs back, as a measuring "
        "fixture holds it: 'x, y, z: components; ...' (r, z or x, z in the "
        "2-D models; mm, current configuration), each fixing the named "
        "displacement components (letters of the coordinates) of the mesh "
        "node nearest to the point. The symmetry planes stay. Empty: the "
        "minimal support, which removes the rigid-body motions the symmetry "
        "planes leave and nothing more (statically determinate, so the "
        "sprung shape does not depend on it).",
        [this](const std::string &t) { supports = parse_supports(t); });
      d.declare(
        "Measure points",
        "",
        text("points 'x, y, z' separated by ';', or empty"),
        "Where the springback displacement normal to the part is reported "
        "(springback-points.csv, run-summary.txt): at the mesh node nearest "
        "to each point of the formed part ('x, y, z' in 3-D, 'r, z' or "
        "'x, z' in the sections; mm, end of forming), along the sheet's "
        "normal there.",
        [this](const std::string &t) { measure_points = parse_points(t); });
      d.add("Slit",
            slit,
            "The split-ring test (Demeri): the part, a ring trimmed from a "
            "cup's wall (Trimming/Planes), is slit along its generator at +y "
            "before it springs back: the symmetry plane x = 0 of "
            "Geometry/Model = half holds it only where y < 0. The ring's "
            "opening (twice the slit face's displacement along x) goes to "
            "run-summary.txt.");
      d.add("Tolerance",
            tolerance,
            number("-", 0, 1),
            "The release is solved when its residual is at most this "
            "fraction of the released forces (-).");
      d.add("Maximum iterations",
            max_iterations,
            whole_number(1, 1000),
            "Newton iterations of the elasto-plastic release at most (one "
            "when no point yields again).");
      d.add("Sound strain ratio",
            sound_strain_ratio,
            number("-", 1),
            "The rigid-plastic end state is a sound start for the elastic "
            "release where the equivalent plastic strain is at least this "
            "many yield strains sigma_y/E (-); see Unsound volume warning.");
      d.add("Unsound volume warning",
            unsound_volume_warning,
            number("-", 0, 1),
            "Warn when more than this fraction of the part's volume has "
            "less plastic strain than Sound strain ratio yield strains (-): "
            "its end stress is not what an elasto-plastic forming would "
            "leave (doc/theory.md, section 12).");
    }

    void Springback::validate() const
    {
      require(std::isfinite(tolerance) && tolerance > 0,
              "Springback/Tolerance",
              "must be positive");
    }

    void check_springback(const Run &run)
    {
      const auto &sb = run.springback;
      if (!sb.enabled)
        return;
      require(run.material.elastic_given(),
              "Material/Young's modulus",
              "must be given for springback (Springback/Enabled = true): "
              "the release is elastic");
      require(!run.material.anisotropy.non_quadratic(),
              "Material/Yield criterion",
              "is " + run.material.anisotropy.describe() +
                ": the springback release returns to a quadratic yield "
                "surface (von Mises or Hill48) only; switch Springback/"
                "Enabled off or use Hill48 for the release run");
      require(!sb.slit || run.geometry.model == model::Model::half,
              "Springback/Slit",
              "the slit lies in the symmetry plane x = 0 of Geometry/Model = "
              "half, not of " +
                model::name(run.geometry.model));
      require(!sb.slit || run.trimming.any(),
              "Springback/Slit",
              "slits a ring trimmed from the part: give Trimming/Planes "
              "(e.g. 'z > 8; z < 20')");
      const auto  names = model::coordinate_names(run.geometry.model);
      std::string letters;
      for (const auto &n : names)
        letters += n;
      for (const auto &p : sb.supports)
        {
          require(p.coordinates.size() == names.size(),
                  "Springback/Supports",
                  "a point has " + std::to_string(p.coordinates.size()) +
                    " coordinates; Geometry/Model = " +
                    model::name(run.geometry.model) + " needs " +
                    std::to_string(names.size()) + " (" + letters + ")");
          require(p.components.find_first_not_of(letters) == std::string::npos,
                  "Springback/Supports",
                  "components '" + p.components +
                    "' are not among the "
                    "coordinates " +
                    letters +
                    " of Geometry/Model = " + model::name(run.geometry.model));
        }
    }
  } // namespace parameters
} // namespace formsolve
