// Signed distance, closest point and normal on triangulated surfaces against
// exact values: a tessellated sphere (closed) at facet interiors, edges and
// vertices, inside and out, and against the analytic sphere within the
// facets' sagitta; an open cylinder (both sides); an open flat patch beyond
// its edges; a flipped triangle refused; STL files written (ASCII, binary)
// and read back; missing and empty files refused.
#include <formsolve/tools/triangle_surface.h>

#include "check.h"
#include "test_surfaces.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <random>

using namespace dealii;
using namespace formsolve::tools;
using test::cylinder;
using test::icosphere;
using test::refused;
using test::write_stl;

namespace
{
  void sphere_checks()
  {
    const SurfaceMesh     m = icosphere(3);
    const TriangleSurface s(m, "sphere");
    test::close("sphere: closed", s.n_boundary_edges(), 0, 0);
    // A facet's centroid, pushed out and in along its normal.
    const auto    &f = m.triangles[17];
    const Point<3> c =
      (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3.;
    Tensor<1, 3> n = cross_product_3d(m.vertices[f[1]] - m.vertices[f[0]],
                                      m.vertices[f[2]] - m.vertices[f[0]]);
    n /= n.norm();
    for (const double h : {0.3, 1e-3, -1e-3})
      {
        const auto q = s.closest(c + h * n);
        test::close("facet, h = " + std::to_string(h), q.distance, h, 1e-12);
        test::close("facet: closest point", (q.closest - c).norm(), 0, 1e-12);
        test::close("facet: normal", (q.normal - n).norm(), 0, 1e-12);
      }
    // A vertex, from outside along its direction, and the point itself.
    const Point<3> v = m.vertices[f[0]];
    auto           q = s.closest(2. * v);
    test::close("vertex from outside", q.distance, 1., 1e-12);
    test::close("vertex: closest point", (q.closest - v).norm(), 0, 1e-12);
    q = s.closest(v);
    test::close("on the vertex", q.distance, 0, 1e-12);
    test::close("on the vertex: normal outward", q.normal * v, 1, 2e-2);
    // An edge's midpoint along the bisector of its two facets.
    const Point<3> e = 0.5 * (m.vertices[f[0]] + m.vertices[f[1]]);
    q                = s.closest(e * (1. + 0.05 / e.norm()));
    test::close("edge from outside", q.distance, 0.05, 1e-12);
    test::close("edge: closest point", (q.closest - e).norm(), 0, 1e-12);
    // From inside, the nearer of the edge's two facet planes is closer than
    // the edge itself.
    const Point<3> x      = e * (1. - 0.01 / e.norm());
    double         nearer = 1;
    for (const auto &t : m.triangles)
      if (std::count(t.begin(), t.end(), f[0]) +
            std::count(t.begin(), t.end(), f[1]) ==
          2)
        {
          Tensor<1, 3> nt =
            cross_product_3d(m.vertices[t[1]] - m.vertices[t[0]],
                             m.vertices[t[2]] - m.vertices[t[0]]);
          nearer =
            std::min(nearer, std::abs((x - m.vertices[t[0]]) * nt) / nt.norm());
        }
    test::close("edge from inside", s.closest(x).distance, -nearer, 1e-12);
    // Random points: the analytic sphere's distance within the sagitta.
    double edge = 0;
    for (const auto &t : m.triangles)
      edge = std::max(edge, (m.vertices[t[0]] - m.vertices[t[1]]).norm());
    const double sagitta = 1 - std::sqrt(1 - edge * edge / 3);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-2, 2);
    double                                 worst = 0;
    unsigned int                           wrong = 0;
    for (unsigned int i = 0; i < 2000; ++i)
      {
        const Point<3> p(u(random), u(random), u(random));
        const double   d = s.closest(p).distance;
        worst            = std::max(worst, std::abs(d - (p.norm() - 1)));
        wrong += p.norm() > 1 + 1e-9 && d < 0;
        wrong += p.norm() < 1 - sagitta && d > 0;
      }
    test::close("random points: |d - (|p| - 1)| within the sagitta",
                worst <= sagitta,
                1,
                0);
    test::close("random points: sign", wrong, 0, 0);
  }

  void open_surface_checks()
  {
    const TriangleSurface s(cylinder(64, 8), "cylinder");
    test::close("cylinder: two open rims", s.n_boundary_edges(), 128, 0);
    const double sagitta = 1 - std::cos(M_PI / 64);
    for (const double r : {0.2, 0.9, 1.1, 3.})
      {
        const auto q =
          s.closest(Point<3>(r * std::cos(0.3), r * std::sin(0.3), 1.1));
        test::close("cylinder at radius " + std::to_string(r),
                    q.distance,
                    r - 1,
                    sagitta);
      }
    // A flat patch z = 0 on [0,1]^2, normal +z: beyond its edge the side is
    // still told by the edge's normal.
    SurfaceMesh patch;
    patch.vertices  = {Point<3>(0, 0, 0),
                       Point<3>(1, 0, 0),
                       Point<3>(1, 1, 0),
                       Point<3>(0, 1, 0)};
    patch.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    const TriangleSurface flat(patch, "patch");
    test::close("patch above",
                flat.closest(Point<3>(0.4, 0.6, 0.2)).distance,
                0.2,
                1e-14);
    test::close("patch below",
                flat.closest(Point<3>(0.4, 0.6, -0.2)).distance,
                -0.2,
                1e-14);
    test::close("beyond the edge, above",
                flat.closest(Point<3>(2, 0.5, 0.1)).distance,
                std::hypot(1, 0.1),
                1e-14);
    test::close("beyond the edge, below",
                flat.closest(Point<3>(2, 0.5, -0.1)).distance,
                -std::hypot(1, 0.1),
                1e-14);
    test::close("beyond the corner, below",
                flat.closest(Point<3>(2, 2, -0.1)).distance,
                -std::sqrt(2.01),
                1e-14);
    patch.triangles[1] = {{0, 3, 2}};
    test::close(
      "a flipped triangle refused",
      refused([&] { TriangleSurface(patch, "flipped.stl"); },
              "flipped.stl: the triangles are not consistently oriented"),
      1,
      0);
  }

  void file_checks()
  {
    const SurfaceMesh     m = icosphere(2);
    const TriangleSurface reference(m, "sphere");
    for (const bool binary : {false, true})
      {
        const std::string file =
          binary ? "sphere-binary.stl" : "sphere-ascii.stl";
        write_stl(m, file, binary);
        const SurfaceMesh read = read_stl(file);
        test::close(file + ": triangles",
                    read.triangles.size(),
                    m.triangles.size(),
                    0);
        test::close(file + ": shared vertices",
                    read.vertices.size(),
                    m.vertices.size(),
                    0);
        const TriangleSurface s(read, file);
        double                worst = 0;
        for (const Point<3> p :
             {Point<3>(0.3, 1.7, -0.2), Point<3>(0.1, 0.2, 0.3)})
          worst = std::max(worst,
                           std::abs(s.closest(p).distance -
                                    reference.closest(p).distance));
        test::close(file + ": the same distances",
                    worst,
                    0,
                    binary ? 1e-6 : 1e-5);
      }
    test::close("missing file refused",
                refused([] { read_stl("no-such-tool.stl"); },
                        "no-such-tool.stl"),
                1,
                0);
    std::ofstream("empty-tool.stl").close();
    test::close("empty file refused",
                refused([] { read_stl("empty-tool.stl"); }, "empty-tool.stl"),
                1,
                0);
  }
} // namespace

int main()
{
  sphere_checks();
  open_surface_checks();
  file_checks();
  return test::result();
}
