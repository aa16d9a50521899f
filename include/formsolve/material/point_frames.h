// The orthotropy frame at every quadrature point of the locally owned cells,
// computed once per configuration. The frame follows the sheet through the
// deformation gradient from the initial mesh (model::MaterialFrame, a polar
// decomposition by SVD per point); within a step the mesh does not move, so
// the Newton iterations of a step share one set of frames instead of
// decomposing again at every assembly (doc/performance.md, "The point
// frames once per step"). Empty for an isotropic law.
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/model/kinematics.h>

#include <vector>

namespace formsolve
{
  namespace material
  {
    template <int dim>
    class PointFrames
    {
    public:
      /// The frames at the points of @p quadrature on every locally owned
      /// cell, in the configuration of @p mapping (the deformation gradient
      /// against @p reference_mapping); nothing for an isotropic law.
      void compute(const RigidViscoplastic       &material,
                   const model::Kinematics<dim>  &kinematics,
                   const dealii::DoFHandler<dim> &dofs,
                   const dealii::Mapping<dim>    &mapping,
                   const dealii::Mapping<dim>    &reference_mapping,
                   const dealii::Quadrature<dim> &quadrature);

      /// Forget the frames (the mesh moved or changed).
      void clear()
      {
        frames.clear();
        valid = false;
      }
      /// Whether compute() ran since the last clear().
      bool ready() const { return valid; }
      /// The quadrature points per cell compute() used.
      unsigned int points_per_cell() const { return n_points; }

      /// The frames at the points of the cell of active index @p cell
      /// (nullptr for an isotropic law).
      const dealii::Tensor<2, 3> *cell(const unsigned int cell) const
      {
        Assert(valid, dealii::ExcInternalError());
        if (frames.empty())
          return nullptr;
        AssertIndexRange((cell + 1) * n_points, frames.size() + 1);
        return frames.data() + std::size_t(cell) * n_points;
      }

    private:
      std::vector<dealii::Tensor<2, 3>> frames;
      unsigned int                      n_points = 0;
      bool                              valid    = false;
    };
  } // namespace material
} // namespace formsolve
