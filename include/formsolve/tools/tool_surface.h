// A tool's working surface as cells for output (ParaView shows the process):
// quadrilaterals in 3-D, segments of the r-z section in axisymmetry.
#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    /// How much of an unbounded surface to draw.
    struct SurfaceExtent
    {
      double reach = 60; // mm from the z axis the faces and planes extend to
      double wall  = 40; // mm, length of the punch's and die's walls
      /// 3-D: the range of angles about the z axis the model covers
      /// (degrees): 0-90 quarter, -90-90 half, 0-360 full.
      double first_angle = 0, last_angle = 90;
    };

    template <int dim>
    struct ToolSurface
    {
      /// Vertices of the cells, in the current position of the tool.
      std::vector<dealii::Point<dim>> points;
      /// Quadrilaterals (3-D, deal.II's vertex order) or segments (2-D).
      std::vector<std::array<unsigned int, 2 * (dim - 1)>> cells;
      /// Triangles (3-D tools from meshes).
      std::vector<std::array<unsigned int, 3>> triangles;
    };
  } // namespace tools
} // namespace formsolve
