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
    bool read_number(const std::string &text, double &x)
    {
      char *end = nullptr;
      x         = std::strtod(text.c_str(), &end);
      return end != text.c_str() &&
             std::string(end).find_first_not_of(" \t") == std::string::npos &&
             std::isfinite(x);
    }

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
          const bool ok = colon != std::string::npos &&
                          read_number(item.substr(0, colon), a) &&
                          read_number(item.substr(colon + 1), b);
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
