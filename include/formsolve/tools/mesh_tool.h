// A rigid tool given by a triangulated surface from CAD (3-D models): the
// smooth surface its triangles stand for, moved rigidly. The search tree is
// built once in the tool's own frame; a query moves the point, not the tool.
#pragma once

#include <formsolve/tools/rigid_tool.h>
#include <formsolve/tools/triangle_surface.h>

#include <memory>

namespace formsolve
{
  namespace tools
  {
    class MeshTool : public RigidTool<3>
    {
    public:
      /// @p mesh is oriented (surface_orientation.h) and placed. Where its
      /// curvature radius is below @p bend_radius (mm) the sheet bends over
      /// it: distance_to_radius() measures to there. An open surface works
      /// on the side the sheet's mid-plane z = @p sheet_z sees; an open
      /// surface of which the sheet sees nothing is an error naming @p file.
      MeshTool(const std::string  &name,
               const SurfaceMesh  &mesh,
               const std::string  &file,
               const double        feature_angle,
               const double        bend_radius,
               const double        sheet_z,
               const Tensor<1, 3> &velocity);

      /// Said when the open surface's normals were turned to the sheet.
      const std::string &side_note() const { return note; }

      double signed_distance(const Point<3> &p,
                             Tensor<1, 3>   &normal) const override;
      /// Out of reach when no triangle meets the cube of half-size @p reach
      /// about @p p (a box query of the tree, much cheaper than the closest
      /// point far from the surface).
      double       signed_distance_within(const Point<3> &p,
                                          const double    reach,
                                          Tensor<1, 3>   &normal) const override;
      double       distance_to_radius(const Point<3> &p) const override;
      Tensor<1, 3> velocity() const override { return tool_velocity; }
      void set_velocity(const Tensor<1, 3> &v) override { tool_velocity = v; }
      Tensor<1, 3> displacement() const override { return offset; }
      void         advance(const double dt) override;
      double       travel() const override { return travelled; }
      void         restore(const Tensor<1, 3> &displacement,
                           const double        travel) override
      {
        offset    = displacement;
        travelled = travel;
      }
      std::string name() const override { return tool_name; }
      /// The triangles, where the tool is now.
      ToolSurface<3> surface(const SurfaceExtent &extent) const override;

    private:
      std::string                      tool_name;
      TriangleSurface                  faces;
      std::unique_ptr<TriangleSurface> bends;    // null: nowhere curved
      double                           side = 1; // -1: turned over
      std::string                      note;
      Tensor<1, 3>                     tool_velocity;
      Tensor<1, 3>                     offset;
      double                           travelled = 0;
    };

    /// The surface of a Shape = mesh tool: read (surface_file.h), placed by
    /// @p shift (mm) and oriented; @p note receives what orienting changed.
    SurfaceMesh load_tool_mesh(const std::string  &file,
                               const double        facet_size,
                               const Tensor<1, 3> &shift,
                               std::string        &note);
  } // namespace tools
} // namespace formsolve
