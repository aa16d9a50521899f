// Exact distance, closest point and normal of the profile tools against
// hand-computed values on flats, fillets, walls and corners.
#include <formsolve/tools/profile_tool.h>

#include "check.h"

using namespace dealii;
using namespace formsolve::tools;

namespace
{
  void expect(const RigidTool<3> &tool,
              const std::string  &where,
              const Point<3>     &p,
              const double        distance,
              const Tensor<1, 3> &normal)
  {
    Tensor<1, 3> n;
    const double d = tool.signed_distance(p, n);
    test::close(tool.name() + " " + where + " distance", d, distance, 1e-12);
    test::close(tool.name() + " " + where + " |n - n_expected|",
                (n - normal).norm(),
                0,
                1e-12);
    const Point<3> c = tool.closest_point(p);
    Tensor<1, 3>   n2;
    test::close(tool.name() + " " + where + " closest point on surface",
                tool.signed_distance(c, n2),
                0,
                1e-12);
  }

  Tensor<1, 3> vec(const double x, const double y, const double z)
  {
    Tensor<1, 3> t;
    t[0] = x, t[1] = y, t[2] = z;
    return t;
  }
} // namespace

int main()
{
  const double s = std::sqrt(0.5);

  // Round punch: diameter 40, nose radius 8, face at z = 1, above the sheet.
  Planform<3> circle;
  circle.kind   = Planform<3>::Kind::circle;
  circle.radius = 20;
  ProfileTool<3> punch("punch", circle, -1, +1, 1., 8., vec(0, 0, -1));
  expect(punch, "flat face", Point<3>(5, 0, 0.5), 0.5, vec(0, 0, -1));
  expect(punch, "inside face", Point<3>(10, 0, 1.5), -0.5, vec(0, 0, -1));
  // Nose centre at r = 12, z = 9; a point 10 mm from it at 45 degrees.
  expect(punch,
         "fillet",
         Point<3>(12 + 10 * s, 0, 9 - 10 * s),
         2.,
         vec(s, 0, -s));
  // The same on the ray at 30 degrees in the x-y plane.
  {
    const double r = 12 + 10 * s, c = std::cos(M_PI / 6),
                 sn = std::sin(M_PI / 6);
    expect(punch,
           "fillet at 30 deg",
           Point<3>(r * c, r * sn, 9 - 10 * s),
           2.,
           vec(s * c, s * sn, -s));
  }
  expect(punch, "wall", Point<3>(22, 0, 20), 2., vec(1, 0, 0));
  expect(punch, "inside wall", Point<3>(0, 19.5, 20), -0.5, vec(0, 1, 0));
  {
    const Point<3> c =
      punch.closest_point(Point<3>(12 + 10 * s, 0, 9 - 10 * s));
    test::close("punch fillet closest point x", c[0], 12 + 8 * s, 1e-12);
    test::close("punch fillet closest point z", c[2], 9 - 8 * s, 1e-12);
  }
  punch.advance(2.5);
  expect(punch,
         "face after 2.5 mm travel",
         Point<3>(5, 0, -2),
         0.5,
         vec(0, 0, -1));
  test::close("punch travel", punch.travel(), 2.5, 1e-14);

  // Die: opening diameter 42.5, entry radius 8, face at z = 0, below the sheet.
  circle.radius = 21.25;
  ProfileTool<3> die("die", circle, +1, -1, 0., 8., Tensor<1, 3>());
  expect(die, "flange face", Point<3>(30, 0, 0.3), 0.3, vec(0, 0, 1));
  expect(die,
         "fillet",
         Point<3>(29.25 - 9 * s, 0, -8 + 9 * s),
         1.,
         vec(-s, 0, s));
  expect(die, "wall", Point<3>(0, -20, -15), 1.25, vec(0, 1, 0));
  expect(die, "inside flange", Point<3>(40, 0, -0.2), -0.2, vec(0, 0, 1));

  // Blank holder: sharp inner edge at r = 29.25, face at z = 1.05.
  circle.radius = 29.25;
  ProfileTool<3>
    holder("blank holder", circle, +1, +1, 1.05, 0., Tensor<1, 3>());
  expect(holder, "face", Point<3>(40, 0, 1), 0.05, vec(0, 0, -1));
  {
    const double d = std::sqrt(0.25 * 0.25 + 0.05 * 0.05);
    expect(holder,
           "sharp corner",
           Point<3>(29, 0, 1),
           d,
           vec(-0.25 / d, 0, -0.05 / d));
  }

  // Rounded-rectangle punch 40 x 30, corner radius 10, nose radius 5, face z =
  // 0.
  Planform<3> rect;
  rect.kind          = Planform<3>::Kind::rounded_rectangle;
  rect.half_length   = 20;
  rect.half_width    = 15;
  rect.corner_radius = 10;
  ProfileTool<3> square("square punch", rect, -1, +1, 0., 5., vec(0, 0, -1));
  expect(square, "face", Point<3>(0, 0, -0.5), 0.5, vec(0, 0, -1));
  expect(square, "side wall", Point<3>(5, 16, 10), 1., vec(0, 1, 0));
  expect(square, "end wall", Point<3>(-21.5, 3, 10), 1.5, vec(-1, 0, 0));
  {
    const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
    expect(square,
           "corner wall",
           Point<3>(10 + 12 * c, 5 + 12 * sn, 20),
           2.,
           vec(c, sn, 0));
  }
  // Nose on the side: centre at rho = -5, z = 5; a point 7 mm away at 45
  // degrees.
  expect(square,
         "side nose",
         Point<3>(0, 10 + 7 * s, 5 - 7 * s),
         2.,
         vec(0, s, -s));

  // Flat die: an infinite plane z = 0.
  Planform<3>    none;
  ProfileTool<3> plane("plane", none, +1, -1, 0., 0., Tensor<1, 3>());
  expect(plane, "above", Point<3>(100, 50, 0.2), 0.2, vec(0, 0, 1));
  expect(plane, "below, on the axis", Point<3>(0, 0, -0.1), -0.1, vec(0, 0, 1));

  // Axisymmetric model: a round tool in 2-D is the r-z profile of the 3-D
  // tool; distance, normal and lateral distance agree at (r, z) and
  // (r, 0, z).
  {
    Planform<2> circle2;
    circle2.kind   = Planform<2>::Kind::circle;
    circle2.radius = 20;
    Planform<3> circle3;
    circle3.kind   = Planform<3>::Kind::circle;
    circle3.radius = 20;
    ProfileTool<2> punch2("punch", circle2, -1, +1, 1., 8., Tensor<1, 2>());
    ProfileTool<3> punch3("punch", circle3, -1, +1, 1., 8., Tensor<1, 3>());
    ProfileTool<2> die2("die", circle2, +1, -1, 0., 8., Tensor<1, 2>());
    ProfileTool<3> die3("die", circle3, +1, -1, 0., 8., Tensor<1, 3>());
    for (const double r : {0., 5., 12., 19., 20.5, 27., 31.})
      for (const double z : {-3., -0.2, 0.5, 1.5, 6., 12.})
        for (const auto &[tool2, tool3] :
             {std::pair<const RigidTool<2> *, const RigidTool<3> *>{&punch2,
                                                                    &punch3},
              {&die2, &die3}})
          {
            Tensor<1, 2> n2;
            Tensor<1, 3> n3;
            const double d2 = tool2->signed_distance(Point<2>(r, z), n2);
            const double d3 = tool3->signed_distance(Point<3>(r, 0, z), n3);
            const std::string at = tool2->name() +
                                   " profile at r=" + std::to_string(r) +
                                   " z=" + std::to_string(z);
            test::close(at + ": 2-D - 3-D distance", d2 - d3, 0, 1e-12);
            test::close(at + ": normal",
                        std::hypot(n2[0] - n3[0], n2[1] - n3[2]) +
                          std::abs(n3[1]),
                        0,
                        1e-12);
            test::close(at + ": lateral distance",
                        tool2->lateral_distance(Point<2>(r, z)) -
                          tool3->lateral_distance(Point<3>(r, 0, z)),
                        0,
                        1e-12);
          }
    test::close("die lateral distance over its face (r = 31)",
                die2.lateral_distance(Point<2>(31, 0)),
                31 - 20,
                1e-12);
  }

  return test::result();
}
