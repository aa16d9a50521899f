// The blank (sheet) mesh. 3-D: a 2-D planform of the modelled part,
// generated or read from gmsh, extruded into hexahedral layers through the
// thickness. Axisymmetric: the r-z section [0, R] x [0, t].
//
// The p4est coarse mesh is as coarse as isotropic refinement allows: each
// refinement in p4est halves the layers too, so the coarse mesh is the
// planform refined k levels less with layers / 2^k layers, and p4est refines
// it k times (k = initial_mesh_level). Every rank stores the coarse mesh but
// only its share of the fine one.
#pragma once

#include <deal.II/distributed/tria.h>

#include <formsolve/parameters/geometry.h>

namespace formsolve
{
  namespace geometry
  {
    /// Boundary ids of the blank.
    enum BoundaryId : dealii::types::boundary_id
    {
      free_surface = 0, // candidate for contact
      symmetry_x   = 1, // plane x = 0 (half, quarter and plane strain)
      symmetry_y   = 2, // plane y = 0 (3-D quarter model)
      axis         = 3  // r = 0 (axisymmetric model): v_r = 0
    };

    /// Levels refined in p4est from the coarse mesh to the initial mesh: the
    /// largest k <= Planform refinements with 2^k dividing the layers.
    unsigned int initial_mesh_level(const parameters::Mesh &mesh);

    /// Fills @p tria (empty) with the coarse mesh only, as a checkpoint's
    /// forest is loaded onto it (or, serial, to build a trimmed part's mesh
    /// from; the rim's manifold comes with it).
    template <int dim>
    void create_coarse_blank_mesh(const parameters::Geometry &geometry,
                                  const parameters::Mesh     &mesh,
                                  dealii::Triangulation<dim> &tria);

    /// The blank's boundary id of a boundary face with centre @p c in the
    /// reference configuration: a symmetry plane or the axis by its
    /// position, else free_surface.
    template <int dim>
    dealii::types::boundary_id boundary_id(const parameters::Geometry &geometry,
                                           const dealii::Point<dim>   &c);
    /// boundary_id() on every boundary face of @p tria.
    template <int dim>
    void set_boundary_ids(const parameters::Geometry &geometry,
                          dealii::Triangulation<dim> &tria);

    /// Fills @p tria (empty) with the initial mesh of the blank in
    /// 0 <= z <= thickness; dim must be model::space_dimension(geometry.model).
    template <int dim>
    void
    create_blank_mesh(const parameters::Geometry &geometry,
                      const parameters::Mesh     &mesh,
                      dealii::parallel::distributed::Triangulation<dim> &tria);
  } // namespace geometry
} // namespace formsolve
