// Rigid tools given by a planform and a rounded working edge: punch, die and
// blank holder, round (surfaces of revolution) or rounded-rectangular.
#pragma once

#include <formsolve/tools/rigid_tool.h>

namespace formsolve
{
  namespace tools
  {
    /// The tool's outline in the x-y plane and the signed in-plane distance
    /// rho to it (negative inside the outline), with |grad rho| = 1.
    template <int dim>
    struct Planform
    {
      enum class Kind
      {
        circle,
        rounded_rectangle,
        unbounded // the whole plane: a flat tool
      };
      Kind   kind          = Kind::unbounded;
      double radius        = 0; // circle
      double half_length   = 0; // rounded rectangle, along x
      double half_width    = 0; // along y
      double corner_radius = 0;

      /// rho(x, y) and its in-plane gradient.
      double distance(const Point<dim> &p, Tensor<1, dim> &gradient) const;
    };

    /// A solid bounded by a planform and a plane z = z_face, with the edge
    /// between them rounded by a profile radius. In the (rho, z) section the
    /// solid is the rounded quadrant {a >= 0, b >= 0}, a = s_a rho,
    /// b = s_b (z - z_face), which gives the exact distance (doc/theory.md).
    ///  - punch:        inside the planform, above the face (s_a = -1, s_b =
    ///  +1)
    ///  - die:          outside the opening, below the face (s_a = +1, s_b =
    ///  -1)
    ///  - blank holder: outside the opening, above the face (s_a = +1, s_b =
    ///  +1)
    template <int dim>
    class ProfileTool : public RigidTool<dim>
    {
    public:
      ProfileTool(const std::string    &name,
                  const Planform<dim>  &planform,
                  const int             side_a,
                  const int             side_b,
                  const double          z_face,
                  const double          profile_radius,
                  const Tensor<1, dim> &velocity);

      double         signed_distance(const Point<dim> &p,
                                     Tensor<1, dim>   &normal) const override;
      double         distance_to_radius(const Point<dim> &p) const override;
      double         lateral_distance(const Point<dim> &p) const override;
      Tensor<1, dim> velocity() const override { return tool_velocity; }
      void set_velocity(const Tensor<1, dim> &v) override { tool_velocity = v; }
      Tensor<1, dim> displacement() const override { return offset; }
      void           advance(const double dt) override;
      double         travel() const override { return travelled; }
      void           restore(const Tensor<1, dim> &displacement,
                             const double          travel) override
      {
        offset    = displacement;
        travelled = travel;
      }
      std::string name() const override { return tool_name; }
      /// Faces, rounded edge and wall swept along the planform's outline
      /// (source/tools/profile_surface.cc).
      ToolSurface<dim> surface(const SurfaceExtent &extent) const override;

    private:
      std::string    tool_name;
      Planform<dim>  planform;
      int            side_a, side_b;
      double         z_face;
      double         profile_radius;
      Tensor<1, dim> tool_velocity;
      Tensor<1, dim> offset; // translation since the start
      double         travelled = 0;
    };

    /// Signed distance to the rounded quadrant {a >= 0, b >= 0} with corner
    /// radius R, and its gradient (da, db). Exposed for tests.
    double rounded_quadrant_distance(const double a,
                                     const double b,
                                     const double R,
                                     double      &grad_a,
                                     double      &grad_b);
  } // namespace tools
} // namespace formsolve
