// The U-channel measures (springback::channel_measures) on a synthetic
// section: a square U (punch face z = -50 up to x = 30, punch radius 5, wall
// at x = 36 from z = -45 to z = -5, die radius 5, flange z = 0 beyond
// x = 41):
// - at the end of forming: theta1 = theta2 = 90 degrees, a straight wall;
// - sprung with the wall and flange turned by 5 degrees about the wall's
//   foot: theta1 = 95, theta2 = 90 (1e-9), the wall still straight;
// - sprung with the wall bent on a circle of radius 300 mm: rho = 300
//   (1e-6), and the segments' point counts.
#include <formsolve/springback/channel_measures.h>

#include "check.h"

#include <cmath>

using namespace formsolve::springback;

namespace
{
  const ChannelTools tools{35, 5, 36, 5};

  /// The square U, with the sprung shape of @p sprung(X0, end point).
  template <class Spring>
  std::vector<ProfilePoint> profile(const Spring &sprung)
  {
    std::vector<ProfilePoint> p;
    auto add = [&](const double X0, const double x, const double z) {
      ProfilePoint q;
      q.X0     = X0;
      q.end    = {{x, z}};
      q.sprung = sprung(X0, q.end);
      p.push_back(q);
    };
    for (int i = 0; i <= 30; ++i) // bottom
      add(i, i, -50);
    for (int i = 1; i < 10; ++i) // punch radius (not measured)
      add(30 + 0.1 * i,
          30 + 5 * std::sin(i * M_PI / 20),
          -45 - 5 * std::cos(i * M_PI / 20));
    for (int i = 0; i <= 40; ++i) // wall
      add(40 + i, 36, -45 + i);
    for (int i = 0; i <= 30; ++i) // flange
      add(100 + i, 41 + i, 0);
    return p;
  }
} // namespace

int main()
{
  const auto same =
    profile([](double, const std::array<double, 2> &x) { return x; });
  const auto m = channel_measures(same, tools, false);
  test::close("square U: theta1", m.theta1, 90, 1e-9);
  test::close("square U: theta2", m.theta2, 90, 1e-9);
  test::close("square U: straight wall", std::isinf(m.rho), 1, 0);
  test::close("square U: bottom points", m.bottom, 31, 0);
  test::close("square U: wall points (strictly between the radii)",
              m.wall,
              39,
              0);
  test::close("square U: flange points", m.flange, 31, 0);

  // Wall and flange turned by 5 degrees outwards about the wall's foot.
  const double a      = 5 * M_PI / 180;
  const auto   turned = profile([&](double X0, const std::array<double, 2> &x) {
    if (X0 < 40)
      return x;
    const double dx = x[0] - 36, dz = x[1] + 45;
    return std::array<double, 2>{{36 + dx * std::cos(a) + dz * std::sin(a),
                                  -45 - dx * std::sin(a) + dz * std::cos(a)}};
  });
  const auto   t      = channel_measures(turned, tools, true);
  test::close("turned: theta1", t.theta1, 95, 1e-9);
  test::close("turned: theta2", t.theta2, 90, 1e-9);

  // The wall on a circle of radius 300 through its foot, curling inwards.
  const double R      = 300;
  const auto   curled = profile([&](double X0, const std::array<double, 2> &x) {
    if (X0 < 40 || X0 > 80)
      return x;
    const double s = (x[1] + 45) / R; // arc length over R
    return std::array<double, 2>{
      {36 - R * (1 - std::cos(s)), -45 + R * std::sin(s)}};
  });
  const auto   c      = channel_measures(curled, tools, true);
  test::close("curled: rho", c.rho, R, 1e-6);
  return test::result();
}
