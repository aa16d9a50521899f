#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/springback/channel_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace formsolve
{
  namespace springback
  {
    namespace
    {
      using Points     = std::vector<std::array<double, 2>>;
      const double nan = std::numeric_limits<double>::quiet_NaN();

      /// The principal direction of @p p (orthogonal regression), pointing
      /// from its first point to its last.
      std::array<double, 2> direction(const Points &p)
      {
        double mx = 0, mz = 0;
        for (const auto &q : p)
          {
            mx += q[0] / p.size();
            mz += q[1] / p.size();
          }
        double sxx = 0, szz = 0, sxz = 0;
        for (const auto &q : p)
          {
            sxx += (q[0] - mx) * (q[0] - mx);
            szz += (q[1] - mz) * (q[1] - mz);
            sxz += (q[0] - mx) * (q[1] - mz);
          }
        const double          angle = 0.5 * std::atan2(2 * sxz, sxx - szz);
        std::array<double, 2> d{{std::cos(angle), std::sin(angle)}};
        const double          along = (p.back()[0] - p.front()[0]) * d[0] +
                             (p.back()[1] - p.front()[1]) * d[1];
        if (along < 0)
          d = {{-d[0], -d[1]}};
        return d;
      }

      /// The angle (degrees) between a and b.
      double angle(const std::array<double, 2> &a,
                   const std::array<double, 2> &b)
      {
        return std::acos(std::clamp(a[0] * b[0] + a[1] * b[1], -1., 1.)) * 180 /
               M_PI;
      }

      /// The radius of the circle x^2 + z^2 + D x + E z + F = 0 fitted to
      /// @p p by least squares (Kasa); infinite for a straight line.
      double curl_radius(const Points &p)
      {
        dealii::FullMatrix<double> A(3, 3);
        dealii::Vector<double>     b(3), c(3);
        for (const auto &q : p)
          {
            const double row[3] = {q[0], q[1], 1};
            const double rhs    = -(q[0] * q[0] + q[1] * q[1]);
            for (unsigned int i = 0; i < 3; ++i)
              {
                b(i) += row[i] * rhs;
                for (unsigned int j = 0; j < 3; ++j)
                  A(i, j) += row[i] * row[j];
              }
          }
        // A straight wall leaves the normal equations (nearly) singular.
        const double               scale = A.frobenius_norm();
        dealii::FullMatrix<double> inverse(3, 3);
        const double               det = A.determinant();
        if (!(std::abs(det) > 1e-14 * scale * scale * scale))
          return std::numeric_limits<double>::infinity();
        inverse.invert(A);
        inverse.vmult(c, b);
        const double r2 = 0.25 * (c(0) * c(0) + c(1) * c(1)) - c(2);
        return r2 > 0 ? std::sqrt(r2) : std::numeric_limits<double>::infinity();
      }
    } // namespace

    ChannelMeasures channel_measures(const std::vector<ProfilePoint> &input,
                                     const ChannelTools              &tools,
                                     const bool                       sprung)
    {
      auto points = input;
      std::sort(points.begin(),
                points.end(),
                [](const ProfilePoint &a, const ProfilePoint &b) {
                  return a.X0 < b.X0;
                });
      // At the end of forming: the bottom lies on the punch face, the
      // flange on the die face; the wall lies between the radii in height.
      double       z_bottom = std::numeric_limits<double>::max(), z_flange = 0;
      unsigned int n_flange = 0;
      for (const auto &p : points)
        {
          z_bottom = std::min(z_bottom, p.end[1]);
          if (p.end[0] >= tools.die_half_width + tools.die_radius)
            {
              z_flange += p.end[1];
              ++n_flange;
            }
        }
      z_flange = n_flange ? z_flange / n_flange : nan;
      Points bottom, wall, flange;
      for (const auto &p : points)
        {
          const auto &x = sprung ? p.sprung : p.end;
          if (p.end[0] <= tools.punch_half_width - tools.punch_radius)
            bottom.push_back(x);
          else if (p.end[0] >= tools.die_half_width + tools.die_radius)
            flange.push_back(x);
          else if (p.end[1] > z_bottom + tools.punch_radius &&
                   p.end[1] < z_flange - tools.die_radius)
            wall.push_back(x);
        }
      ChannelMeasures m;
      m.bottom = bottom.size();
      m.wall   = wall.size();
      m.flange = flange.size();
      if (m.bottom < 3 || m.wall < 3 || m.flange < 3)
        {
          m.theta1 = m.theta2 = m.rho = nan;
          return m;
        }
      const auto db = direction(bottom), dw = direction(wall),
                 df = direction(flange);
      m.theta1      = angle({{-db[0], -db[1]}}, dw);
      m.theta2      = angle({{-dw[0], -dw[1]}}, df);
      m.rho         = curl_radius(wall);
      return m;
    }
  } // namespace springback
} // namespace formsolve
