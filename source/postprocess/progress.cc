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

    void Progress::record(const double wall, const double travel)
    {
      points.emplace_back(wall, travel);
      if (points.size() > window + 1)
        points.pop_front();
    }

    double Progress::time_left(const double stroke) const
    {
      if (points.size() < 2)
        return -1;
      const double dw = points.back().first - points.front().first;
      const double ds = points.back().second - points.front().second;
      if (ds <= 0)
        return -1;
      return dw / ds * std::max(0., stroke - points.back().second);
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
