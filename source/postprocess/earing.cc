#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/earing.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace formsolve
{
  namespace postprocess
  {
    namespace
    {
      /// The angle (degrees from x) mapped into the modelled range by the
      /// model's symmetry planes: x = 0 mirrors theta to 180 - theta, y = 0
      /// to -theta.
      double modelled(double theta, const model::Model m)
      {
        theta = std::remainder(theta, 360.); // (-180, 180]
        if (model::symmetric_in_y(m))
          theta = std::abs(theta);
        if (model::symmetric_in_x(m) && std::abs(theta) > 90)
          theta = (theta > 0 ? 180. : -180.) - theta;
        return theta;
      }

      /// Linear in the angle between the rim samples (sorted), or NaN
      /// outside them.
      double interpolate(const std::vector<std::pair<double, double>> &s,
                         const double                                  theta)
      {
        for (std::size_t i = 1; i < s.size(); ++i)
          if (s[i - 1].first <= theta + 1e-9 && theta <= s[i].first + 1e-9)
            {
              const double w =
                s[i].first > s[i - 1].first
                  ? (theta - s[i - 1].first) / (s[i].first - s[i - 1].first)
                  : 0.;
              return s[i - 1].second + w * (s[i].second - s[i - 1].second);
            }
        return std::nan("");
      }
    } // namespace

    EaringProfile earing_profile(const std::vector<SheetColumn<3>> &cols,
                                 const model::Model                 m,
                                 const double rolling_direction,
                                 const double step)
    {
      EaringProfile p;
      double        bottom = 1e300;
      for (const auto &c : cols)
        bottom = std::min(bottom, c.bottom);
      std::vector<std::pair<double, double>> rim; // (angle from x, height)
      for (const auto &c : cols)
        if (c.rim)
          rim.emplace_back(std::atan2(c.mid[1], c.mid[0]) * 180 / M_PI,
                           c.top - bottom);
      if (rim.size() < 2)
        return p;
      std::sort(rim.begin(), rim.end());
      // Angles from RD over the full circle; heights where the model has
      // the rim (through its symmetry).
      std::vector<double> full;
      for (double a = 0; a < 360 - 1e-9; a += step)
        full.push_back(interpolate(rim, modelled(a + rolling_direction, m)));
      const double lo = *std::min_element(full.begin(), full.end()),
                   hi = *std::max_element(full.begin(), full.end());
      double sum      = 0;
      for (const double h : full)
        sum += h / full.size();
      p.mean      = sum;
      p.amplitude = hi - lo;
      // Ears: maxima of the periodic profile whose prominence (the drop to
      // the higher of the two lowest points before a higher height on
      // either side) is at least a quarter of the amplitude, so that a
      // wiggle on an ear's crest is not a second ear. A rim within 0.5 % of
      // the mean height counts as flat: the quarter-disk mesh alone makes
      // an isotropic rim wavy by 0.09 mm (0.3 %) on the earing cup.
      const std::size_t n = full.size();
      for (std::size_t i = 0; i < n && p.amplitude >= 0.005 * p.mean; ++i)
        {
          if (!(full[i] >= full[(i + n - 1) % n] &&
                full[i] > full[(i + 1) % n]))
            continue;
          double low[2] = {full[i], full[i]};
          for (int side = 0; side < 2; ++side)
            for (std::size_t k = 1; k < n; ++k)
              {
                const double h = full[side ? (i + k) % n : (i + n - k) % n];
                if (h > full[i])
                  break;
                low[side] = std::min(low[side], h);
              }
          if (full[i] - std::max(low[0], low[1]) >= 0.25 * p.amplitude)
            p.ear_angles.push_back(i * step);
        }
      p.ears = p.ear_angles.size();
      // The profile over the modelled range, angles from RD.
      const double range =
        model::symmetric_in_x(m) && model::symmetric_in_y(m)   ? 90.
        : model::symmetric_in_x(m) || model::symmetric_in_y(m) ? 180.
                                                               : 360. - step;
      for (double a = 0; a <= range + 1e-9; a += step)
        {
          p.angle.push_back(a);
          p.height.push_back(
            full[static_cast<std::size_t>(std::round(a / step)) % n]);
        }
      return p;
    }

    void write_earing(const EaringProfile &p, const std::string &directory)
    {
      if (p.angle.empty())
        return;
      std::ostringstream f;
      f.precision(8);
      f << "angle_deg,cup_height_mm\n";
      for (std::size_t i = 0; i < p.angle.size(); ++i)
        f << p.angle[i] << ',' << p.height[i] << '\n';
      write_atomically(directory + "/earing.csv",
                       [&](std::ostream &o) { o << f.str(); });
    }
  } // namespace postprocess
} // namespace formsolve
