#include <formsolve/parameters/flow_curve_file.h>
#include <formsolve/parameters/require.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    std::vector<std::pair<double, double>>
    read_flow_curve(const std::string &file)
    {
      const std::string entry = "Material/Flow curve file";
      std::ifstream     in(file);
      require(in.good(), entry, "cannot read '" + file + "'");
      std::vector<std::pair<double, double>> points;
      std::string                            line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          for (auto &c : line)
            if (c == ',' || c == ';' || c == '\t')
              c = ' ';
          const auto start = line.find_first_not_of(" \r");
          if (start == std::string::npos || line[start] == '#')
            continue;
          std::istringstream s(line);
          double             strain = 0, stress = 0;
          if (!(s >> strain >> stress))
            {
              // A header line of words, only before the first point.
              require(points.empty(),
                      entry,
                      file + ", line " + std::to_string(number) +
                        ": not 'strain, stress' (two numbers)");
              continue;
            }
          const std::string where = file + ", line " + std::to_string(number);
          require(std::isfinite(strain) && std::isfinite(stress),
                  entry,
                  where + ": not finite numbers");
          require(stress > 0, entry, where + ": the stress must be > 0 MPa");
          require(points.empty() ? strain >= 0 : strain > points.back().first,
                  entry,
                  where + ": the strains must start at 0 or above and "
                          "increase");
          require(points.empty() || stress >= points.back().second,
                  entry,
                  where + ": the stress falls; a softening flow curve has "
                          "no unique flow (give a hardening one)");
          points.emplace_back(strain, stress);
        }
      require(points.size() >= 2,
              entry,
              file + " holds " + std::to_string(points.size()) +
                " point(s); at least 2 (strain, stress MPa) are needed");
      return points;
    }
  } // namespace parameters
} // namespace formsolve
