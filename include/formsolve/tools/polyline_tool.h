// A rigid tool of the axisymmetric model given by its r-z profile from a
// file (Shape = mesh: a CSV of points or gmsh lines): the smooth curve its
// segments stand for, moved rigidly along z.
#pragma once

#include <formsolve/tools/profile_file.h>
#include <formsolve/tools/rigid_tool.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    class PolylineTool : public RigidTool<2>
    {
    public:
      /// A closed chain of @p lines is the section of the tool's solid (its
      /// outside works); an open chain is its working face, on the side the
      /// sheet's mid-plane z = @p sheet_z sees along z (a chain the sheet
      /// cannot see is an error naming @p file). Segments whose normals
      /// differ by more than @p feature_angle (degrees) meet at a sharp
      /// corner; elsewhere the profile is smoothed. Where its curvature
      /// radius is below @p bend_radius (mm) the sheet bends over it.
      PolylineTool(const std::string  &name,
                   const ProfileLines &lines,
                   const std::string  &file,
                   const double        feature_angle,
                   const double        bend_radius,
                   const double        sheet_z,
                   const Tensor<1, 2> &velocity);

      /// What orienting changed, to be said (empty: nothing).
      const std::string &orientation_note() const { return note; }

      double       signed_distance(const Point<2> &p,
                                   Tensor<1, 2>   &normal) const override;
      double       signed_distance_within(const Point<2> &p,
                                          const double    reach,
                                          Tensor<1, 2>   &normal) const override;
      double       distance_to_radius(const Point<2> &p) const override;
      Tensor<1, 2> velocity() const override { return tool_velocity; }
      void set_velocity(const Tensor<1, 2> &v) override { tool_velocity = v; }
      Tensor<1, 2> displacement() const override { return offset; }
      void         advance(const double dt) override;
      double       travel() const override { return travelled; }
      void         restore(const Tensor<1, 2> &displacement,
                           const double        travel) override
      {
        offset    = displacement;
        travelled = travel;
      }
      std::string    name() const override { return tool_name; }
      ToolSurface<2> surface(const SurfaceExtent &extent) const override;

    private:
      /// The closest point of the segments (no smoothing) to @p p in the
      /// tool's frame: segment, parameter t in [0, 1], point.
      struct Closest
      {
        unsigned int segment = 0;
        double       t       = 0;
        Point<2>     point;
        double       distance = 0; // unsigned
      };
      Closest closest(const Point<2> &p) const;
      /// Chains head to tail, turned so that closed ones face outwards and
      /// open ones face the sheet.
      void orient(const std::string &file, const double sheet_z);

      std::string                              tool_name;
      std::vector<Point<2>>                    points;
      std::vector<std::array<unsigned int, 2>> segments;
      std::vector<Tensor<1, 2>>                normal; // per segment
      /// Normal at each end of each segment: the vertex normal where the
      /// profile is smooth, the segment's own at a sharp corner or an end.
      std::vector<std::array<Tensor<1, 2>, 2>> corner_normal;
      /// Normal for the sign at each end (the mean of the segments there).
      std::vector<std::array<Tensor<1, 2>, 2>> end_normal;
      std::vector<unsigned int>                bends;     // segments bent over
      Point<2>                                 low, high; // bounding box
      std::string                              note;
      Tensor<1, 2>                             tool_velocity;
      Tensor<1, 2>                             offset;
      double                                   travelled = 0;
    };
  } // namespace tools
} // namespace formsolve
