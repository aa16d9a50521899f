// The distributed coarse mesh (geometry/blank_mesh.cc) refined by p4est to
// the initial mesh must be the mesh a serial refinement gives: the planform
// refined with its manifolds (the circle of a round blank), extruded into the
// layers. Checked by the vertex positions, the number of cells, the volume
// and the area per boundary id, for round (quarter, half, full) and
// rectangular blanks, layer counts giving k = 0, 1, 2 p4est levels, and the
// axisymmetric section.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>

#include "check.h"

#include <algorithm>
#include <map>

using namespace dealii;
using namespace formsolve;

namespace
{
  /// The serial mesh the way it was built before p4est refined it.
  void reference_3d(const parameters::Geometry &g,
                    const parameters::Mesh     &m,
                    Triangulation<3>           &mesh)
  {
    const double     R = 0.5 * g.blank_diameter;
    Triangulation<2> planform;
    if (g.blank_shape == parameters::BlankShape::rectangle)
      GridGenerator::subdivided_hyper_rectangle(planform,
                                                {2, 1},
                                                Point<2>(0, 0),
                                                Point<2>(0.5 * g.blank_length,
                                                         0.5 * g.blank_width));
    else if (g.model == model::Model::quarter)
      GridGenerator::quarter_hyper_ball(planform, Point<2>(), R);
    else if (g.model == model::Model::half)
      {
        GridGenerator::half_hyper_ball(planform, Point<2>(), R);
        double x = 0;
        for (const auto &cell : planform.active_cell_iterators())
          x += cell->center()[0];
        if (x < 0)
          GridTools::rotate(M_PI, planform);
      }
    else
      GridGenerator::hyper_ball(planform, Point<2>(), R);
    planform.refine_global(m.refinements);
    Triangulation<2> flat;
    GridGenerator::flatten_triangulation(planform, flat);
    std::vector<double> z(m.layers + 1);
    for (unsigned int k = 0; k <= m.layers; ++k)
      z[k] = g.thickness * k / m.layers;
    GridGenerator::extrude_triangulation(flat, z, mesh);
  }

  template <int dim>
  std::vector<Point<dim>> used_vertices(const Triangulation<dim> &t)
  {
    std::vector<Point<dim>> v;
    std::vector<bool>       used(t.n_vertices(), false);
    for (const auto &cell : t.active_cell_iterators())
      for (const auto i : cell->vertex_indices())
        if (!used[cell->vertex_index(i)])
          {
            used[cell->vertex_index(i)] = true;
            v.push_back(cell->vertex(i));
          }
    return v;
  }

  template <int dim>
  void compare(const std::string          &name,
               const parameters::Geometry &g,
               const parameters::Mesh     &m,
               const Triangulation<dim>   &reference,
               const unsigned int          expected_level)
  {
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    geometry::create_blank_mesh(g, m, tria);
    test::close(name + ": p4est levels",
                geometry::initial_mesh_level(m),
                expected_level,
                0);
    test::close(name + ": coarse cells x 2^(dim k)",
                tria.n_cells(0) * std::pow(2., dim * expected_level),
                reference.n_active_cells(),
                0);
    test::close(name + ": active cells",
                tria.n_global_active_cells(),
                reference.n_active_cells(),
                0);
    // Hausdorff distance of the vertex sets (equal sizes).
    const auto a = used_vertices(tria), b = used_vertices(reference);
    double     gap = a.size() == b.size() ? 0 : 1e9;
    for (const auto *pair : {&a, &b})
      for (const auto &p : *pair)
        {
          double nearest = 1e9;
          for (const auto &q : pair == &a ? b : a)
            nearest = std::min(nearest, p.distance(q));
          gap = std::max(gap, nearest);
        }
    test::close(name + ": largest vertex distance (mm)", gap, 0, 1e-9);

    // Volume and boundary area per id (the faces' flat geometry); the
    // reference's ids from where its faces lie.
    auto expected_id = [&](const Point<dim> &c) -> int {
      const double tol = 1e-9;
      if (dim == 2)
        return c[0] < tol ? geometry::axis : geometry::free_surface;
      if (std::abs(c[dim - 1]) < tol ||
          std::abs(c[dim - 1] - g.thickness) < tol)
        return geometry::free_surface;
      if (model::symmetric_in_x(g.model) && std::abs(c[0]) < tol)
        return geometry::symmetry_x;
      if (model::symmetric_in_y(g.model) && std::abs(c[1]) < tol)
        return geometry::symmetry_y;
      return geometry::free_surface;
    };
    auto measures = [&](const Triangulation<dim> &t, const bool own_ids) {
      std::map<int, double> s;
      for (const auto &cell : t.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            s[-1] += cell->measure();
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                s[own_ids ? face->boundary_id()
                          : expected_id(face->center())] += face->measure();
          }
      return s;
    };
    const auto got = measures(tria, true), want = measures(reference, false);
    test::close(name + ": boundary ids used", got.size(), want.size(), 0);
    for (const auto &[id, value] : want)
      test::close(name + (id < 0 ? ": volume"
                                 : ": area of boundary " + std::to_string(id)),
                  got.count(id) ? got.at(id) : 0.,
                  value,
                  1e-10 * value);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  parameters::Geometry g;
  g.blank_diameter = 60;
  g.blank_length   = 60;
  g.blank_width    = 30;
  g.thickness      = 0.8;
  parameters::Mesh m;
  m.refinements = 3;

  using model::Model;
  using parameters::BlankShape;
  for (const auto &[model, shape, label] :
       {std::tuple{Model::quarter, BlankShape::round, "quarter round"},
        std::tuple{Model::half, BlankShape::round, "half round"},
        std::tuple{Model::full, BlankShape::round, "full round"},
        std::tuple{Model::quarter, BlankShape::rectangle, "quarter rectangle"}})
    for (const auto &[layers, k] : {std::pair{4u, 2u}, {6u, 1u}, {3u, 0u}})
      {
        g.model       = model;
        g.blank_shape = shape;
        m.layers      = layers;
        Triangulation<3> reference;
        reference_3d(g, m, reference);
        compare<3>(std::string(label) + ", " + std::to_string(layers) +
                     " layers",
                   g,
                   m,
                   reference,
                   k);
      }

  // Axisymmetric: (2^(r+1) x layers) rectangles.
  g.model       = Model::axisymmetric;
  g.blank_shape = BlankShape::round;
  for (const auto &[layers, k] : {std::pair{4u, 2u}, {3u, 0u}})
    {
      m.layers = layers;
      Triangulation<2> reference;
      GridGenerator::subdivided_hyper_rectangle(reference,
                                                {2u << m.refinements, layers},
                                                Point<2>(0, 0),
                                                Point<2>(30, g.thickness));
      compare<2>("axisymmetric, " + std::to_string(layers) + " layers",
                 g,
                 m,
                 reference,
                 k);
    }

  // Adaptive refinement beyond the initial mesh keeps the geometry: the rim
  // is round as far as the initial mesh, and a refined rim edge is split at
  // its midpoint (a drawn rim must not bulge out, nor the sheet gain volume).
  // Twice, for each number of p4est refinements k.
  g.model       = Model::quarter;
  g.blank_shape = BlankShape::round;
  for (const unsigned int layers : {4u, 6u, 3u})
    {
      m.layers = layers;
      parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
      geometry::create_blank_mesh(g, m, tria);
      const double volume     = GridTools::volume(tria);
      double       off_circle = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->manifold_id() == 1)
            for (const auto v : face->vertex_indices())
              {
                const Point<3> &p = face->vertex(v);
                off_circle =
                  std::max(off_circle, std::abs(std::hypot(p[0], p[1]) - 30));
              }
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->center().norm() > 0.9 * 30)
              cell->set_refine_flag();
          tria.execute_coarsening_and_refinement();
        }
      const std::string label = std::to_string(layers) + " layers";
      test::close("initial rim on the circle, " + label + " (mm)",
                  off_circle,
                  0,
                  1e-9);
      test::close("rim refined twice keeps the volume, " + label + " (rel.)",
                  GridTools::volume(tria) / volume - 1,
                  0,
                  1e-12);
    }
  return test::result();
}
