// The blank (sheet) mesh: a 2-D planform, generated or read from gmsh,
// extruded into hexahedral layers through the thickness.
#pragma once

#include <deal.II/distributed/tria.h>

#include <formsolve/parameters/parameters.h>

namespace formsolve
{
  namespace geometry
  {
    /// Boundary ids of the blank.
    enum BoundaryId : dealii::types::boundary_id
    {
      free_surface = 0, // candidate for contact
      symmetry_x   = 1, // plane x = 0
      symmetry_y   = 2  // plane y = 0
    };

    /// Fills @p tria (empty) with the blank in 0 <= z <= thickness.
    void
    create_blank_mesh(const parameters::Geometry                      &geometry,
                      const parameters::Mesh                          &mesh,
                      dealii::parallel::distributed::Triangulation<3> &tria);
  } // namespace geometry
} // namespace formsolve
