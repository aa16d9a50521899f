#include <formsolve/postprocess/progress.h>

#include <cmath>
#include <cstdio>

namespace formsolve
{
  namespace postprocess
  {
    Progress::Progress(const unsigned int window)
        : window(window)
    {}

    void
    Progress::record(const double wall, const double travel, const double to_go)
    {
      points.push_back({wall, travel, to_go});
      if (points.size() > window + 1)
        points.pop_front();
    }

    double Progress::end_travel(const double beyond) const
    {
      const double inf = std::numeric_limits<double>::infinity();
      if (points.size() < 2 || !std::isfinite(points.back().to_go))
        return inf;
      const auto  &a = points.front(), &b = points.back();
      const double rate = (a.to_go - b.to_go) / (b.travel - a.travel);
      if (!(rate > 0))
        return inf;
      return b.travel + std::max(0., b.to_go) / rate + beyond;
    }

    double Progress::time_left(const double end) const
    {
      if (points.size() < 2)
        return -1;
      const auto  &a = points.front(), &b = points.back();
      const double ds = b.travel - a.travel;
      if (ds <= 0 || !std::isfinite(end))
        return -1;
      return (b.wall - a.wall) / ds * std::max(0., end - b.travel);
    }

    std::string Progress::duration(const double s)
    {
      char buffer[64];
      if (s < 0)
        return "?";
      if (s < 60)
        std::snprintf(buffer, sizeof buffer, "%.1f s", s);
      else if (s < 3600)
        std::snprintf(buffer,
                      sizeof buffer,
                      "%d min %02d s",
                      int(s) / 60,
                      int(s) % 60);
      else
        std::snprintf(buffer,
                      sizeof buffer,
                      "%d h %02d min",
                      int(s) / 3600,
                      (int(s) % 3600) / 60);
      return buffer;
    }
  } // namespace postprocess
} // namespace formsolve
