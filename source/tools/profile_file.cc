#include <deal.II/base/exceptions.h>

#include <formsolve/tools/profile_file.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    ProfileLines read_profile_csv(const std::string &file,
                                  const std::string &what,
                                  const std::string &names,
                                  const bool         on_axis_side)
    {
      std::ifstream in(file);
      AssertThrow(in.good(),
                  ExcMessage(what + " '" + file +
                             "': no such file "
                             "or not readable"));
      ProfileLines p;
      std::string  line;
      unsigned int number = 0;
      while (std::getline(in, line))
        {
          ++number;
          std::replace(line.begin(), line.end(), ',', ' ');
          std::istringstream s(line);
          std::string        first;
          if (!(s >> first) || first[0] == '#')
            continue;
          std::istringstream values(line);
          double             r = 0, z = 0;
          std::string        rest;
          const bool         ok = bool(values >> r >> z) && !(values >> rest);
          // A header line (words, no numbers) may come first.
          if (!ok && p.points.empty() && number == 1 &&
              !std::isdigit(static_cast<unsigned char>(first.back())))
            continue;
          AssertThrow(ok,
                      ExcMessage(what + " '" + file + "', line " +
                                 std::to_string(number) +
                                 ": expected two numbers " + names +
                                 " (mm), got `" + line + "`"));
          AssertThrow(r >= 0 || !on_axis_side,
                      ExcMessage(what + " '" + file + "', line " +
                                 std::to_string(number) +
                                 ": r must not be negative (the axis is r = "
                                 "0)"));
          if (!p.points.empty())
            p.segments.push_back(
              {{static_cast<unsigned int>(p.points.size() - 1),
                static_cast<unsigned int>(p.points.size())}});
          p.points.emplace_back(r, z);
        }
      AssertThrow(p.points.size() >= 2,
                  ExcMessage(what + " '" + file + "': fewer than two points " +
                             names));
      return p;
    }

    ProfileLines read_profile(const std::string &file, const double facet_size)
    {
      std::string extension = std::filesystem::path(file).extension();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      if (extension == ".csv")
        return read_profile_csv(file);
      if (extension == ".msh" || extension == ".geo")
        return read_profile_with_gmsh(file, facet_size);
      AssertThrow(false,
                  ExcMessage("tool profile file '" + file +
                             "': unknown kind; the axisymmetric model takes "
                             "a CSV of r, z points (.csv) or gmsh lines "
                             "(.msh, .geo)"));
      return {};
    }
  } // namespace tools
} // namespace formsolve
