#include <formsolve/tools/mesh_tool.h>
#include <formsolve/tools/surface_orientation.h>

#include <cmath>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    MeshTool::MeshTool(const std::string  &name,
                       const SurfaceMesh  &mesh,
                       const std::string  &file,
                       const double        feature_angle,
                       const double        bend_radius,
                       const double        sheet_z,
                       const Tensor<1, 3> &velocity)
        : tool_name(name)
        , faces(mesh, file, feature_angle)
        , tool_velocity(velocity)
    {
      if (faces.n_boundary_edges() > 0)
        {
          // An open surface is a working face: its side is the one the
          // sheet sees.
          const double seen = faces.area_seen_from(sheet_z);
          AssertThrow(seen != 0,
                      ExcMessage(file +
                                 ": an open surface of which the sheet "
                                 "sees nothing along z, so its working "
                                 "side cannot be told; give the tool's "
                                 "closed surface, or place it facing the "
                                 "sheet (Mesh offset)"));
          if (seen < 0)
            {
              side = -1;
              note = file + ": the open surface's normals point away from "
                            "the sheet: turned to face it";
            }
        }
      const SurfaceMesh curved = faces.curved_part(bend_radius);
      if (!curved.triangles.empty())
        bends = std::make_unique<TriangleSurface>(curved, file, feature_angle);
    }

    double MeshTool::signed_distance(const Point<3> &p,
                                     Tensor<1, 3>   &normal) const
    {
      const auto q = faces.smooth(p - offset);
      normal       = side * q.normal;
      return side * q.distance;
    }

    double MeshTool::signed_distance_within(const Point<3> &p,
                                            const double    reach,
                                            Tensor<1, 3>   &normal) const
    {
      if (!faces.near(p - offset, reach))
        return 2 * reach;
      return signed_distance(p, normal);
    }

    double MeshTool::distance_to_radius(const Point<3> &p) const
    {
      if (!bends)
        return std::numeric_limits<double>::infinity();
      return std::abs(bends->closest(p - offset).distance);
    }

    void MeshTool::advance(const double dt)
    {
      offset += dt * tool_velocity;
      travelled += dt * tool_velocity.norm();
    }

    ToolSurface<3> MeshTool::surface(const SurfaceExtent &extent) const
    {
      // The part of the tool over the modelled range of angles and within
      // the reach, as the analytic tools are drawn: a quarter model's
      // output, mirrored by the viewer, shows the whole tool once.
      ToolSurface<3> s;
      for (const auto &x : faces.points())
        s.points.push_back(x + offset);
      const double full = extent.last_angle - extent.first_angle >= 360;
      for (const auto &t : faces.triangles())
        {
          const Point<3> c =
            (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.;
          double angle = std::atan2(c[1], c[0]) * 180 / M_PI;
          if (angle < extent.first_angle - 1e-9)
            angle += 360;
          if (std::hypot(c[0], c[1]) <= extent.reach &&
              (full || angle <= extent.last_angle + 1e-9))
            s.triangles.push_back(t);
        }
      return s;
    }

    SurfaceMesh load_tool_mesh(const std::string  &file,
                               const double        facet_size,
                               const Tensor<1, 3> &shift,
                               std::string        &note)
    {
      SurfaceMesh mesh = read_surface(file, facet_size);
      for (auto &x : mesh.vertices)
        x += shift;
      note = orient(mesh, file).describe(file);
      return mesh;
    }
  } // namespace tools
} // namespace formsolve
