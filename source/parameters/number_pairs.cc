#include <formsolve/parameters/number_pairs.h>
#include <formsolve/parameters/require.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    std::vector<std::pair<double, double>> read_pairs(const std::string &text,
                                                      const std::string &entry,
                                                      const std::string &form)
    {
      std::vector<std::pair<double, double>> points;
      std::string                            item;
      std::istringstream                     in(text);
      while (std::getline(in, item, ','))
        {
          if (item.find_first_not_of(" \t") == std::string::npos)
            continue;
          const auto colon = item.find(':');
          double     a = 0, b = 0;
          bool       ok = colon != std::string::npos;
          if (ok)
            {
              const std::string x = item.substr(0, colon),
                                y = item.substr(colon + 1);
              char *end           = nullptr;
              a                   = std::strtod(x.c_str(), &end);
              ok                  = end != x.c_str() &&
                   std::string(end).find_first_not_of(" \t") ==
                     std::string::npos &&
                   std::isfinite(a);
              b  = std::strtod(y.c_str(), &end);
              ok = ok && end != y.c_str() &&
                   std::string(end).find_first_not_of(" \t") ==
                     std::string::npos &&
                   std::isfinite(b);
            }
          const auto first = item.find_first_not_of(" \t");
          const auto last  = item.find_last_not_of(" \t");
          require(ok,
                  entry,
                  "'" + item.substr(first, last - first + 1) + "' is not '" +
                    form + "' with finite numbers");
          points.emplace_back(a, b);
        }
      return points;
    }

    double
    piecewise_linear(const std::vector<std::pair<double, double>> &points,
                     const double                                  x)
    {
      if (x <= points.front().first)
        return points.front().second;
      if (x >= points.back().first)
        return points.back().second;
      const auto hi = std::upper_bound(points.begin(),
                                       points.end(),
                                       x,
                                       [](const double v, const auto &p) {
                                         return v < p.first;
                                       });
      const auto lo = hi - 1;
      return lo->second + (hi->second - lo->second) * (x - lo->first) /
                            (hi->first - lo->first);
    }
  } // namespace parameters
} // namespace formsolve
