// The interface every rigid tool offers to contact: exact geometry and motion.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <formsolve/tools/tool_surface.h>

#include <limits>
#include <string>

namespace formsolve
{
  namespace tools
  {
    using dealii::Point;
    using dealii::Tensor;

    template <int dim>
    class RigidTool
    {
    public:
      virtual ~RigidTool() = default;

      /// Signed distance from @p p to the tool surface: positive outside the
      /// tool, negative inside (penetration). @p normal receives the unit
      /// outward normal of the tool at the closest point.
      virtual double signed_distance(const Point<dim> &p,
                                     Tensor<1, dim>   &normal) const = 0;

      /// signed_distance() where |d| < @p reach; elsewhere any value of at
      /// least @p reach (and @p normal unset): tools whose query is costly
      /// (meshes) skip points out of reach, such as the contact search's.
      virtual double signed_distance_within(const Point<dim> &p,
                                            const double      reach,
                                            Tensor<1, dim>   &normal) const
      {
        (void)reach;
        return signed_distance(p, normal);
      }

      /// The point of the tool surface closest to @p p.
      Point<dim> closest_point(const Point<dim> &p) const
      {
        Tensor<1, dim> n;
        const double   d = signed_distance(p, n);
        return p - d * n;
      }

      /// Distance from @p p to the tool's profile-radius arc, where the sheet
      /// bends (mm); infinite for tools without one. Drives mesh refinement.
      virtual double distance_to_radius(const Point<dim> & /*p*/) const
      {
        return std::numeric_limits<double>::infinity();
      }

      /// In-plane distance of @p p from the edge of the tool's face (mm):
      /// positive on the face's side (over the die face, under the holder
      /// or punch face), negative in the opening; infinite for flat tools.
      virtual double lateral_distance(const Point<dim> & /*p*/) const
      {
        return std::numeric_limits<double>::infinity();
      }

      /// Rigid translation velocity of the tool (mm/s).
      virtual Tensor<1, dim> velocity() const = 0;

      /// Set the translation velocity (a tool under force control).
      virtual void set_velocity(const Tensor<1, dim> &v) = 0;

      /// Translation since the start (mm).
      virtual Tensor<1, dim> displacement() const = 0;

      /// Translate the tool by velocity() * dt.
      virtual void advance(const double dt) = 0;

      /// Distance travelled so far (mm).
      virtual double travel() const = 0;

      /// Put the tool back where a checkpoint found it.
      virtual void restore(const Tensor<1, dim> &displacement,
                           const double          travel) = 0;

      virtual std::string name() const = 0;
      /// The working surface in the tool's current position, drawn over
      /// @p extent where the tool is unbounded.
      virtual ToolSurface<dim> surface(const SurfaceExtent &extent) const = 0;
    };
  } // namespace tools
} // namespace formsolve
