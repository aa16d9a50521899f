// The trim line's signed side function (trimming::TrimShape), positive where
// the part is kept, against hand-computed distances: half-spaces (3-D and
// the axisymmetric r, z), a closed plan-view curve (inside and outside, in
// either winding), an open one (left and right of its segments; at its end
// points and at a vertex, by the mean of the two segments' normals), a
// surface (behind and in front of its normals), and several cuts at once
// (the smallest side). Files are written to the working directory.
#include <deal.II/base/mpi.h>

#include <formsolve/trimming/trim_shape.h>

#include "check.h"

#include <cmath>
#include <fstream>

using namespace dealii;
using namespace formsolve;
using parameters::CurveSide;
using parameters::SurfaceSide;

namespace
{
  parameters::Trimming cut_by_curve(const std::string &file,
                                    const CurveSide    side)
  {
    parameters::Trimming t;
    t.curve_file = file;
    t.curve_side = side;
    return t;
  }

  double
  side(const parameters::Trimming &t, const model::Model m, const Point<3> &p)
  {
    return trimming::TrimShape<3>(t, m, MPI_COMM_WORLD).side(p);
  }

  void write(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       quarter = model::Model::quarter;
  const auto                       full    = model::Model::full;

  // Half-spaces: z < -6 and z > -12 keep a ring 6 mm high.
  parameters::Trimming ring;
  ring.planes = parameters::parse_plane_cuts("z < -6; z > -12");
  test::close("ring, mid-height", side(ring, quarter, {3, 4, -9}), 3, 1e-12);
  test::close("ring, above", side(ring, quarter, {3, 4, -5}), -1, 1e-12);
  test::close("ring, below", side(ring, quarter, {3, 4, -14}), -2, 1e-12);
  parameters::Trimming oblique;
  oblique.planes = parameters::parse_plane_cuts("3 x + 4 y > 10");
  test::close("oblique plane (unit normal)",
              side(oblique, quarter, {2, 2, 0}),
              (14. - 10.) / 5.,
              1e-12);
  {
    parameters::Trimming flange;
    flange.planes = parameters::parse_plane_cuts("r < 28");
    trimming::TrimShape<2> s(flange,
                             model::Model::axisymmetric,
                             MPI_COMM_WORLD);
    test::close("axisymmetric r < 28", s.side(Point<2>(30, -1)), -2, 1e-12);
    test::close("no cut is empty",
                trimming::TrimShape<2>(parameters::Trimming(),
                                       model::Model::axisymmetric,
                                       MPI_COMM_WORLD)
                  .empty(),
                1,
                0);
  }

  // A closed square 0..10, counter-clockwise and clockwise.
  write("trim_square_ccw.csv", "x,y\n0,0\n10,0\n10,10\n0,10\n0,0\n");
  write("trim_square_cw.csv", "# clockwise\n0,0\n0,10\n10,10\n10,0\n0,0\n");
  for (const std::string file : {"trim_square_ccw.csv", "trim_square_cw.csv"})
    {
      const auto in  = cut_by_curve(file, CurveSide::inside);
      const auto out = cut_by_curve(file, CurveSide::outside);
      test::close(file + ": inside, centre",
                  side(in, full, {5, 5, 7}),
                  5,
                  1e-12);
      test::close(file + ": inside, near an edge",
                  side(in, full, {5, 9, -3}),
                  1,
                  1e-12);
      test::close(file + ": inside, a point outside",
                  side(in, full, {12, 5, 0}),
                  -2,
                  1e-12);
      test::close(file + ": inside, beyond a corner",
                  side(in, full, {13, 14, 0}),
                  -5,
                  1e-12);
      test::close(file + ": outside, a point outside",
                  side(out, full, {12, 5, 0}),
                  2,
                  1e-12);
      test::close(file + ": outside, centre",
                  side(out, full, {5, 5, 0}),
                  -5,
                  1e-12);
    }

  // An open polyline (0,0) -> (10,0) -> (10,10): left is +y along the first
  // segment and -x along the second.
  write("trim_open.csv", "0,0\n10,0\n10,10\n");
  const auto left  = cut_by_curve("trim_open.csv", CurveSide::left);
  const auto right = cut_by_curve("trim_open.csv", CurveSide::right);
  test::close("open, left of the first segment",
              side(left, full, {5, 1, 0}),
              1,
              1e-12);
  test::close("open, right of the first segment",
              side(left, full, {5, -1, 0}),
              -1,
              1e-12);
  test::close("open, left of the second segment",
              side(left, full, {8, 5, 0}),
              2,
              1e-12);
  test::close("open, right: the same negated",
              side(right, full, {8, 5, 0}),
              -2,
              1e-12);
  // At the corner (10, 0) from outside: the mean normal (-1, 1)/sqrt2 puts
  // (12, -2) on the right, sqrt 8 away.
  test::close("open, beyond the vertex",
              side(left, full, {12, -2, 0}),
              -std::sqrt(8.),
              1e-12);
  // Beyond the first point: its segment's normal, distance to the point.
  test::close("open, before the first point",
              side(left, full, {-2, 1, 0}),
              std::sqrt(5.),
              1e-12);
  test::close("open, past the last point",
              side(left, full, {11, 12, 0}),
              -std::sqrt(5.),
              1e-12);

  // A surface: the plane z = 1 as two triangles with normals +z.
  write("trim_plane.stl",
        "solid p\n"
        "facet normal 0 0 1\nouter loop\nvertex -50 -50 1\nvertex 50 -50 "
        "1\nvertex 50 50 1\nendloop\nendfacet\n"
        "facet normal 0 0 1\nouter loop\nvertex -50 -50 1\nvertex 50 50 "
        "1\nvertex -50 50 1\nendloop\nendfacet\n"
        "endsolid p\n");
  parameters::Trimming behind;
  behind.surface_file   = "trim_plane.stl";
  behind.surface_side   = SurfaceSide::behind;
  auto in_front         = behind;
  in_front.surface_side = SurfaceSide::in_front;
  test::close("surface, behind its normals",
              side(behind, full, {3, 2, -0.5}),
              1.5,
              1e-12);
  test::close("surface, in front",
              side(in_front, full, {3, 2, -0.5}),
              -1.5,
              1e-12);
  test::close("surface, in front, above it",
              side(in_front, full, {3, 2, 4}),
              3,
              1e-12);

  // Every cut at once: the smallest side.
  auto all   = cut_by_curve("trim_square_ccw.csv", CurveSide::inside);
  all.planes = parameters::parse_plane_cuts("z < 0.5");
  test::close("curve and plane: the plane decides",
              side(all, full, {5, 5, 0.25}),
              0.25,
              1e-12);
  test::close("curve and plane: the curve decides",
              side(all, full, {9.5, 5, -3}),
              0.5,
              1e-12);
  return test::result();
}
