// Axisymmetric tools from r-z profiles (Shape = mesh in the axisymmetric
// model). The smooth profile (Phong's quadratic over the segments) against a
// circle: its distance error falls with the fourth power of the segment
// length, and is far below the segments' own; the sign on both sides of a
// sharp corner; closed chains turned outwards and open ones to the sheet
// (reversed CSV order gives the same distances); the die's profile read as
// CSV and from gmsh (.geo meshed, x-z and x-y planes) against the analytic
// die; the bending region; bad files refused naming them.
#include <formsolve/tools/polyline_tool.h>
#include <formsolve/tools/profile_tool.h>

#include "check.h"
#include "test_surfaces.h"

#include <cmath>
#include <fstream>

using namespace dealii;
using namespace formsolve::tools;
using test::refused;

namespace
{
  /// A circle of radius @p R about (r0, z0) as a closed chain of n
  /// segments, counter-clockwise if @p ccw.
  ProfileLines circle(const unsigned int n, const double R, const bool ccw)
  {
    ProfileLines p;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double a = (ccw ? 1 : -1) * 2 * M_PI * i / n;
        p.points.emplace_back(30 + R * std::cos(a), 5 + R * std::sin(a));
        p.segments.push_back({{i, (i + 1) % n}});
      }
    return p;
  }

  /// Largest |distance error| over points at offset @p h from the circle,
  /// at segment midpoints and vertices (angles on a fine grid).
  double circle_error(const PolylineTool &t, const double R, const double h)
  {
    double worst = 0;
    for (unsigned int k = 0; k < 720; ++k)
      {
        const double   a = 2 * M_PI * (k + 0.37) / 720;
        const Point<2> p(30 + (R + h) * std::cos(a), 5 + (R + h) * std::sin(a));
        Tensor<1, 2>   n;
        worst = std::max(worst, std::abs(t.signed_distance(p, n) - h));
      }
    return worst;
  }

  void write(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }
} // namespace

int main()
{
  const Tensor<1, 2> still;
  // Smooth circle: fourth order in the segment length, far below the
  // segments' own error (second order).
  double last = 0;
  for (const unsigned int n : {16u, 32u, 64u})
    {
      const PolylineTool
                   t("circle", circle(n, 4, true), "circle", 30, 0, 100, still);
      const double e = circle_error(t, 4, 0.1);
      // The segments' own error: the sagitta R (1 - cos(pi/n)).
      const double sagitta = 4 * (1 - std::cos(M_PI / n));
      std::cout << n << " segments: smooth error " << e << ", segments "
                << sagitta << "\n";
      test::close("smooth profile 10x closer than the segments at " +
                    std::to_string(n),
                  e < 0.1 * sagitta,
                  1,
                  0);
      if (last > 0)
        test::close("error falls >= 8-fold per halving", last / e >= 8, 1, 0);
      last = e;
    }
  // A clockwise circle is turned to face outwards, and says so.
  {
    const PolylineTool
                 t("circle", circle(32, 4, false), "cw.csv", 30, 0, 100, still);
    Tensor<1, 2> n;
    test::close("clockwise circle turned: inside negative",
                t.signed_distance(Point<2>(30, 5), n),
                -4,
                0.01);
    test::close("and said",
                t.orientation_note().find("turned to face outwards") !=
                  std::string::npos,
                1,
                0);
  }
  // The default cup's die as an open CSV profile, in both orders: the
  // analytic die's distances within the smoothing's error, the sign on
  // both sides, the sheet's side found.
  const std::string forward = "die-forward.csv", backward = "die-backward.csv";
  std::string       f = "r, z\n", b;
  std::vector<std::string> rows;
  rows.push_back("60, 0\n");
  for (unsigned int i = 0; i <= 32; ++i)
    {
      const double a = M_PI / 2 + M_PI / 2 * i / 32;
      rows.push_back(std::to_string(29.25 + 8 * std::cos(a)) + ", " +
                     std::to_string(-8 + 8 * std::sin(a)) + "\n");
    }
  rows.push_back("21.25, -45\n");
  for (const auto &r : rows)
    f += r;
  for (auto r = rows.rbegin(); r != rows.rend(); ++r)
    b += *r;
  write(forward, f);
  write(backward, b);
  Planform<2> opening;
  opening.kind   = Planform<2>::Kind::circle;
  opening.radius = 21.25;
  const ProfileTool<2> exact("die", opening, +1, -1, 0, 8, still);
  for (const std::string &file : {forward, backward})
    {
      const PolylineTool
             t("die", read_profile(file, 1), file, 30, 15.6, 0.39, still);
      double worst = 0;
      for (const Point<2> &p : {Point<2>(40, 0.3),
                                Point<2>(40, -0.2),
                                Point<2>(24, -1),
                                Point<2>(26, -2.5),
                                Point<2>(22, -6),
                                Point<2>(20.5, -20),
                                Point<2>(22, -20)})
        {
          Tensor<1, 2> n, m;
          worst = std::max(worst,
                           std::abs(t.signed_distance(p, n) -
                                    exact.signed_distance(p, m)));
        }
      test::close(file + ": the analytic die's distances", worst, 0, 2e-4);
      test::close(file + ": refinement near the radius, not on the face",
                  t.distance_to_radius(Point<2>(26, -1)) < 1 &&
                    t.distance_to_radius(Point<2>(50, 0)) > 10,
                  1,
                  0);
    }
  // A sharp corner (the holder's edge): the sign right on both sides.
  write("holder.csv", "29.25, 10.78\n29.25, 0.78\n60, 0.78\n");
  {
    const PolylineTool t("holder",
                         read_profile("holder.csv", 1),
                         "holder.csv",
                         30,
                         15.6,
                         0.39,
                         still);
    Tensor<1, 2>       n;
    test::close("beside the holder's edge, in the opening",
                t.signed_distance(Point<2>(29, 0.7), n),
                std::hypot(0.25, 0.08),
                1e-12);
    test::close("under the face",
                t.signed_distance(Point<2>(35, 0.5), n),
                0.28,
                1e-12);
    test::close("inside the holder",
                t.signed_distance(Point<2>(35, 1), n),
                -0.22,
                1e-12);
  }
  // gmsh: the same die drawn in the x-z plane and in the x-y plane.
  write("die-xz.geo",
        "SetFactory(\"OpenCASCADE\");\nPoint(1) = {60, 0, 0};\n"
        "Point(2) = {29.25, 0, 0};\nPoint(3) = {29.25, 0, -8};\n"
        "Point(4) = {21.25, 0, -8};\nPoint(5) = {21.25, 0, -45};\n"
        "Line(1) = {1, 2};\nCircle(2) = {2, 3, 4};\nLine(3) = {4, 5};\n");
  write("die-xy.geo",
        "SetFactory(\"OpenCASCADE\");\nPoint(1) = {60, 0, 0};\n"
        "Point(2) = {29.25, 0, 0};\nPoint(3) = {29.25, -8, 0};\n"
        "Point(4) = {21.25, -8, 0};\nPoint(5) = {21.25, -45, 0};\n"
        "Line(1) = {1, 2};\nCircle(2) = {2, 3, 4};\nLine(3) = {4, 5};\n");
  for (const std::string file : {"die-xz.geo", "die-xy.geo"})
    {
      const PolylineTool
        t("die", read_profile(file, 0.5), file, 30, 15.6, 0.39, still);
      Tensor<1, 2>   n, m;
      const Point<2> p(25, -2);
      test::close(file + ": on the radius as the analytic die",
                  t.signed_distance(p, n),
                  exact.signed_distance(p, m),
                  2e-4);
    }
  // Bad files, each named.
  write("one.csv", "1, 2\n");
  write("words.csv", "1, 2\n3, x\n");
  write("tee.csv", "0, 0\n1, 0\n");
  write("wall.csv", "20, -5\n20, -45\n");
  test::close("missing file",
              refused([] { read_profile("no.csv", 1); }, "no.csv"),
              1,
              0);
  test::close("one point",
              refused([] { read_profile("one.csv", 1); },
                      "fewer than two points"),
              1,
              0);
  test::close("not a number",
              refused([] { read_profile("words.csv", 1); },
                      "words.csv', line 2"),
              1,
              0);
  test::close("unknown kind",
              refused([] { read_profile("die.stl", 1); }, "CSV of r, z points"),
              1,
              0);
  test::close("a wall the sheet cannot see",
              refused(
                [&] {
                  PolylineTool("w",
                               read_profile("wall.csv", 1),
                               "wall.csv",
                               30,
                               15.6,
                               0.39,
                               still);
                },
                "sheet sees nothing"),
              1,
              0);
  {
    ProfileLines tee;
    tee.points   = {Point<2>(0, 0),
                    Point<2>(1, 0),
                    Point<2>(2, 0),
                    Point<2>(1, 1)};
    tee.segments = {{{0, 1}}, {{1, 2}}, {{1, 3}}};
    test::close(
      "three lines at a point",
      refused([&] { PolylineTool("t", tee, "tee", 30, 1, -1, still); },
              "3 lines meet"),
      1,
      0);
  }
  return test::result();
}
