// Triangulated tool surfaces from files: STL (ASCII or binary), in mm.
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
    };

    /// The surface of an STL file (ASCII or binary; CGAL's reader, which
    /// merges the facets' equal corners into shared vertices). A missing,
    /// empty or unreadable file is an error naming it.
    SurfaceMesh read_stl(const std::string &file);
  } // namespace tools
} // namespace formsolve
