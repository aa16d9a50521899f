// Meshed tools beyond the facets. The smooth surface (Phong, doc/theory.md
// eq. 7b) against a sphere and a cylinder, with a cube's sharp edges kept
// exact; orientation made to agree (turned triangles and inside-out parts
// counted; triangles given twice left out and coincident vertices joined;
// three triangles on an edge and a Moebius strip refused); the
// working side of an open surface taken from the sheet, and a surface the
// sheet cannot see refused; the bending region found from the curvature;
// gmsh's readers (.msh with quadrilaterals, .geo and STEP meshed at a facet
// size) and bad files refused naming them.
#include <formsolve/tools/mesh_tool.h>
#include <formsolve/tools/surface_orientation.h>
#include <formsolve/tools/triangle_surface.h>

#include "check.h"
#include "test_surfaces.h"

#include <fstream>
#include <random>

using namespace dealii;
using namespace formsolve::tools;
using test::refused;

namespace
{
  /// The unit cube's 12 triangles, normals outward.
  SurfaceMesh cube()
  {
    SurfaceMesh m;
    for (unsigned int i = 0; i < 8; ++i)
      m.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    m.triangles = {{{0, 2, 3}},
                   {{0, 3, 1}},
                   {{4, 5, 7}},
                   {{4, 7, 6}},
                   {{0, 1, 5}},
                   {{0, 5, 4}},
                   {{2, 6, 7}},
                   {{2, 7, 3}},
                   {{0, 4, 6}},
                   {{0, 6, 2}},
                   {{1, 3, 7}},
                   {{1, 7, 5}}};
    return m;
  }

  double volume(const SurfaceMesh &m)
  {
    double v = 0;
    for (const auto &t : m.triangles)
      v += m.vertices[t[0]] * cross_product_3d(Tensor<1, 3>(m.vertices[t[1]]),
                                               Tensor<1, 3>(m.vertices[t[2]]));
    return v / 6;
  }

  double area(const SurfaceMesh &m)
  {
    double a = 0;
    for (const auto &t : m.triangles)
      a += 0.5 * cross_product_3d(m.vertices[t[1]] - m.vertices[t[0]],
                                  m.vertices[t[2]] - m.vertices[t[0]])
                   .norm();
    return a;
  }

  /// Largest errors of the facets and of the smooth surface against the
  /// unit sphere, and of the smooth normal against the radial direction.
  void smooth_sphere()
  {
    std::mt19937                           random(5);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double>                    smooth_error;
    for (const unsigned int levels : {2u, 3u, 4u})
      {
        const TriangleSurface s(test::icosphere(levels), "sphere");
        double                facet = 0, smooth = 0, normal = 0;
        for (unsigned int i = 0; i < 4000; ++i)
          {
            Point<3> p(u(random), u(random), u(random));
            p *= (1 + 0.01 * u(random)) / p.norm();
            const double exact = p.norm() - 1;
            facet = std::max(facet, std::abs(s.closest(p).distance - exact));
            const auto q = s.smooth(p);
            smooth       = std::max(smooth, std::abs(q.distance - exact));
            normal       = std::max(normal, (q.normal - p / p.norm()).norm());
          }
        std::cout << "sphere, " << s.n_triangles()
                  << " triangles: facets off by " << facet
                  << ", smooth surface by " << smooth << ", its normal by "
                  << normal << "\n";
        test::close("sphere " + std::to_string(levels) +
                      ": smooth surface 10x closer than the facets",
                    smooth <= facet / 10,
                    1,
                    0);
        smooth_error.push_back(smooth);
      }
    // Fourth order: 16-fold per halving of the edges; asked for 8.
    for (unsigned int k = 1; k < smooth_error.size(); ++k)
      test::close("sphere: smooth error falls 8-fold per halving",
                  smooth_error[k] <= smooth_error[k - 1] / 8,
                  1,
                  0);
  }

  void sharp_edges()
  {
    // On a cube every edge is sharp: the smooth query is the exact one.
    const TriangleSurface                  s(cube(), "cube");
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    double                                 largest = 0;
    for (unsigned int i = 0; i < 2000; ++i)
      {
        const Point<3> p(u(random), u(random), u(random));
        largest =
          std::max(largest,
                   std::abs(s.smooth(p).distance - s.closest(p).distance));
      }
    test::close("cube: sharp edges kept", largest, 0, 1e-12);
    // The open cylinder's rims are boundaries, its side smooth.
    const TriangleSurface c(test::cylinder(32, 4), "cylinder");
    const double          sagitta = 1 - std::cos(M_PI / 32);
    const auto            q =
      c.smooth(Point<3>(1.2 * std::cos(0.05), 1.2 * std::sin(0.05), 0.7));
    test::close("cylinder: smooth side, 20x better than the sagitta",
                std::abs(q.distance - 0.2) < sagitta / 20,
                1,
                0);
  }

  void orientation()
  {
    SurfaceMesh inverted = cube();
    for (auto &t : inverted.triangles)
      std::swap(t[1], t[2]);
    auto r = orient(inverted, "inverted.stl");
    test::close("inside-out cube turned", r.turned_out, 1, 0);
    test::close("inside-out cube: volume", volume(inverted), 1, 1e-14);
    test::close("... said", !r.describe("inverted.stl").empty(), 1, 0);

    SurfaceMesh mixed = cube();
    std::swap(mixed.triangles[4][1], mixed.triangles[4][2]);
    std::swap(mixed.triangles[9][1], mixed.triangles[9][2]);
    r = orient(mixed, "mixed.stl");
    test::close("two turned triangles", r.turned, 2, 0);
    test::close("... no part inside out", r.turned_out, 0, 0);
    test::close("... volume", volume(mixed), 1, 1e-14);

    SurfaceMesh sphere = test::icosphere(2);
    for (auto &t : sphere.triangles)
      std::swap(t[1], t[2]);
    std::swap(sphere.triangles[7][1], sphere.triangles[7][2]);
    r = orient(sphere, "sphere.stl");
    test::close("sphere: one turned, inside out", r.turned, 1, 0);
    test::close("sphere: inside out", r.turned_out, 1, 0);
    test::close("sphere: volume positive", volume(sphere) > 4, 1, 0);

    SurfaceMesh patch;
    patch.vertices  = {Point<3>(0, 0, 0),
                       Point<3>(1, 0, 0),
                       Point<3>(1, 1, 0),
                       Point<3>(0, 1, 0),
                       Point<3>(2, 0, 0),
                       Point<3>(2, 1, 0)};
    patch.triangles = {{{0, 1, 2}},
                       {{0, 2, 3}},
                       {{1, 2, 5}},
                       {{1, 4, 5}},
                       {{2, 2, 3}}};
    r               = orient(patch, "patch.stl");
    test::close("open patch: the minority turned", r.turned, 1, 0);
    test::close("open patch: the triangle without area left out",
                r.degenerate,
                1,
                0);
    test::close("open patch: majority kept (normals +z)",
                cross_product_3d(patch.vertices[patch.triangles[2][1]] -
                                   patch.vertices[patch.triangles[2][0]],
                                 patch.vertices[patch.triangles[2][2]] -
                                   patch.vertices[patch.triangles[2][0]])[2] >
                  0,
                1,
                0);

    // A cube as exporters write it: one triangle twice, one twice with
    // the other orientation, one corner given again as a vertex of its own.
    SurfaceMesh repeated = cube();
    repeated.triangles.push_back(repeated.triangles[3]);
    repeated.triangles.push_back({{repeated.triangles[5][0],
                                   repeated.triangles[5][2],
                                   repeated.triangles[5][1]}});
    repeated.vertices.push_back(repeated.vertices[repeated.triangles[0][0]]);
    repeated.triangles[0][0] = repeated.vertices.size() - 1;
    r                        = orient(repeated, "repeated.stl");
    test::close("repeated triangles left out", r.repeated, 2, 0);
    test::close("... the corner joined", r.joined, 1, 0);
    test::close("... a closed cube again: 12 triangles, 8 vertices",
                repeated.triangles.size() + repeated.vertices.size(),
                20,
                0);
    test::close("... volume", volume(repeated), 1, 1e-14);
    test::close("... said",
                r.describe("repeated.stl").find("2 triangles given twice") !=
                  std::string::npos,
                1,
                0);

    SurfaceMesh fin = cube();
    fin.vertices.emplace_back(0.5, -1, 0.5);
    fin.triangles.push_back({{0, 1, 8}});
    test::close("three triangles on an edge refused",
                refused([&] { orient(fin, "fin.stl"); },
                        "fin.stl: three or more triangles share the edge"),
                1,
                0);

    // A Moebius strip of 8 quads, each split in two.
    SurfaceMesh  strip;
    const double n = 8;
    for (unsigned int i = 0; i < n; ++i)
      for (const double s : {-0.3, 0.3})
        {
          const double phi = 2 * M_PI * i / n;
          const double w   = s * std::cos(phi / 2);
          strip.vertices.emplace_back((1 + w) * std::cos(phi),
                                      (1 + w) * std::sin(phi),
                                      s * std::sin(phi / 2));
        }
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int a = 2 * i, b = 2 * i + 1;
        // The last quad joins the first with its sides swapped.
        const unsigned int c = i + 1 < n ? 2 * i + 2 : 1,
                           d = i + 1 < n ? 2 * i + 3 : 0;
        strip.triangles.push_back({{a, c, d}});
        strip.triangles.push_back({{a, d, b}});
      }
    test::close("Moebius strip refused",
                refused([&] { orient(strip, "strip.stl"); },
                        "strip.stl: the surface cannot be oriented"),
                1,
                0);
  }

  void working_side()
  {
    // A die face z = 0 below a sheet at mid-plane z = 0.4, its normals
    // pointing down: turned to face the sheet.
    SurfaceMesh patch;
    patch.vertices  = {Point<3>(-5, -5, 0),
                       Point<3>(5, -5, 0),
                       Point<3>(5, 5, 0),
                       Point<3>(-5, 5, 0)};
    patch.triangles = {{{0, 2, 1}}, {{0, 3, 2}}};
    Tensor<1, 3>   still, normal;
    const MeshTool down("die", patch, "face.stl", 30, 20, 0.4, still);
    test::close("open face turned to the sheet",
                !down.side_note().empty(),
                1,
                0);
    test::close("... sheet above at +0.4",
                down.signed_distance(Point<3>(1, 2, 0.4), normal),
                0.4,
                1e-14);
    test::close("... normal +z", normal[2], 1, 1e-14);
    test::close("a flat face bends nothing",
                std::isinf(down.distance_to_radius(Point<3>(0, 0, 1))),
                1,
                0);
    for (auto &t : patch.triangles)
      std::swap(t[1], t[2]);
    const MeshTool up("die", patch, "face.stl", 30, 20, 0.4, still);
    test::close("facing the sheet: kept", up.side_note().empty(), 1, 0);
    // A wall the sheet does not see along z.
    SurfaceMesh wall;
    wall.vertices  = {Point<3>(0, -5, 1),
                      Point<3>(0, 5, 1),
                      Point<3>(0, 5, 6),
                      Point<3>(0, -5, 6)};
    wall.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    test::close(
      "a wall the sheet cannot see refused",
      refused([&] { MeshTool("punch", wall, "wall.stl", 30, 20, 0.4, still); },
              "wall.stl: an open surface of which the sheet sees nothing"),
      1,
      0);
    // The bending region: a unit sphere is curved for bend radii above 1.
    const auto sphere = test::icosphere(3);
    test::close("sphere curved below a bend radius of 2",
                std::isfinite(MeshTool("p", sphere, "s", 30, 2, -5, still)
                                .distance_to_radius(Point<3>(0, 0, 3))),
                1,
                0);
    test::close("... not below 0.5",
                std::isinf(MeshTool("p", sphere, "s", 30, 0.5, -5, still)
                             .distance_to_radius(Point<3>(0, 0, 3))),
                1,
                0);
  }

  void gmsh_files()
  {
    std::ofstream("two-quads.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n"
         "3 1 1 0\n4 0 1 0\n5 2 0 0\n6 2 1 0\n$EndNodes\n$Elements\n2\n"
         "1 3 2 0 1 1 2 3 4\n2 3 2 0 1 2 5 6 3\n$EndElements\n";
    const auto quads = read_surface("two-quads.msh", 1);
    test::close(".msh quadrilaterals: 4 triangles",
                quads.triangles.size(),
                4,
                0);
    test::close(".msh: area", area(quads), 2, 1e-14);

    std::ofstream("box.geo")
      << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 10, 10, 2};\n";
    auto box = read_surface("box.geo", 2);
    test::close(".geo meshed: area", area(box), 280, 1e-9);
    orient(box, "box.geo");
    test::close(".geo: closed",
                TriangleSurface(box, "box.geo").n_boundary_edges(),
                0,
                0);
    test::close(".geo: volume", volume(box), 200, 1e-9);
    unsigned int longest_ok = 1;
    for (const auto &t : box.triangles)
      for (unsigned int k = 0; k < 3; ++k)
        longest_ok &=
          (box.vertices[t[k]] - box.vertices[t[(k + 1) % 3]]).norm() <= 2 * 1.5;
    test::close(".geo: facets about the size asked for", longest_ok, 1, 0);
    // gmsh writes STEP from the geometry; read back and meshed.
    const int written = std::system("gmsh -0 box.geo -o box.step > /dev/null");
    test::close("gmsh wrote box.step", written, 0, 0);
    auto step = read_surface("box.step", 2);
    orient(step, "box.step");
    test::close("STEP meshed: volume", volume(step), 200, 1e-9);

    std::ofstream("garbage.msh") << "this is not a mesh\n";
    test::close("garbage .msh refused",
                refused([] { read_surface("garbage.msh", 1); },
                        "tool surface file 'garbage.msh': gmsh reading failed"),
                1,
                0);
    test::close("missing .step refused",
                refused([] { read_surface("no-such-die.step", 1); },
                        "'no-such-die.step': no such file"),
                1,
                0);
    test::close("unknown kind refused",
                refused([] { read_surface("die.obj", 1); },
                        "'die.obj': unknown kind"),
                1,
                0);
  }
} // namespace

int main()
{
  smooth_sphere();
  sharp_edges();
  orientation();
  working_side();
  gmsh_files();
  return test::result();
}
