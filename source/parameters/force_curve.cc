#include <formsolve/parameters/force_curve.h>
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
    ForceCurve ForceCurve::read(const std::string &text,
                                const std::string &entry)
    {
      if (text.find(':') == std::string::npos)
        {
          double f = 0;
          require(read_number(text, f),
                  entry,
                  "`" + text +
                    "` is not accepted; it takes a force in N, or a table "
                    "'travel:force, ...' of punch travel (mm) and force (N)");
          return constant(f);
        }
      ForceCurve c;
      c.points = read_pairs(text, entry, "travel:force");
      require(!c.points.empty(), entry, "the table has no point");
      for (std::size_t i = 1; i < c.points.size(); ++i)
        require(c.points[i].first > c.points[i - 1].first,
                entry,
                "the punch travels must increase: " +
                  str(c.points[i - 1].first) + " is followed by " +
                  str(c.points[i].first));
      require(c.points.front().first >= 0,
              entry,
              "the punch travels start at 0 mm or later, got " +
                str(c.points.front().first));
      return c;
    }

    double ForceCurve::at(const double travel) const
    {
      return piecewise_linear(points, travel);
    }

    double ForceCurve::smallest() const
    {
      double f = points.front().second;
      for (const auto &p : points)
        f = std::min(f, p.second);
      return f;
    }

    double ForceCurve::largest() const
    {
      double f = points.front().second;
      for (const auto &p : points)
        f = std::max(f, p.second);
      return f;
    }

    std::string ForceCurve::text() const
    {
      if (!varies())
        return str(points.front().second);
      std::ostringstream s;
      for (std::size_t i = 0; i < points.size(); ++i)
        s << (i ? ", " : "") << points[i].first << ":" << points[i].second;
      return s.str();
    }
  } // namespace parameters
} // namespace formsolve
