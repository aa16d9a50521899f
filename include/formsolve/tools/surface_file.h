// Triangulated tool surfaces from files, in mm: STL (ASCII or binary), gmsh
// meshes, and geometry (.geo, STEP, IGES, BREP) meshed by gmsh.
#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    using dealii::Point;
    using dealii::Tensor;

    /// Vertices and triangles; a triangle's normal (v1 - v0) x (v2 - v0)
    /// points to the working side (outside the tool).
    struct SurfaceMesh
    {
      std::vector<Point<3>>                    vertices;
      std::vector<std::array<unsigned int, 3>> triangles;

      /// For the broadcast from the rank that read it.
      template <class Archive>
      void serialize(Archive &archive, const unsigned int)
      {
        archive &vertices &triangles;
      }
    };

    /// The surface of an STL file (ASCII or binary; CGAL's reader, which
    /// merges the facets' equal corners into shared vertices). A missing,
    /// empty or unreadable file is an error naming it.
    SurfaceMesh read_stl(const std::string &file);

    /// The triangles of a gmsh mesh (.msh; quadrilaterals split in two), or
    /// of the surfaces gmsh meshes from geometry (.geo, .step, .stp, .iges,
    /// .igs, .brep) with triangle edges up to @p facet_size (mm). Read with
    /// the gmsh library deal.II links.
    SurfaceMesh read_with_gmsh(const std::string &file,
                               const double       facet_size);

    /// Whether triangle @p t of @p mesh has an area to give it a normal:
    /// |(v1 - v0) x (v2 - v0)| > 1e-12 (|v1 - v0|^2 + |v2 - v0|^2). The one
    /// test by which tool surfaces leave triangles out.
    bool has_area(const SurfaceMesh                 &mesh,
                  const std::array<unsigned int, 3> &t);

    /// read_stl or read_with_gmsh by the file's extension; any other
    /// extension is an error naming the file and the accepted ones.
    SurfaceMesh read_surface(const std::string &file, const double facet_size);
  } // namespace tools
} // namespace formsolve
