// The point frame of one cell, always present: Hill's map M = T(R) S at the
// quadrature points, with R the orthotropy frame turned with the sheet
// (model::MaterialFrame), what the point law needs besides the strain rate
// (RigidViscoplastic::evaluate); none for an isotropic law, so that the
// callers pass map(q) whatever the law and only material/ tells the laws
// apart.
#pragma once

#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/material_frame.h>

#include <vector>

namespace formsolve
{
  namespace material
  {
    template <int dim>
    class HillOrientation
    {
    public:
      explicit HillOrientation(const RigidViscoplastic &material);

      /// What the frame needs of the cell kinematics at its points: the
      /// deformation gradient from the reference configuration (Hill's), or
      /// nothing (an isotropic law).
      dealii::UpdateFlags update_flags() const
      {
        return material.isotropic() ? dealii::update_default
                                    : dealii::update_jacobians;
      }
      bool needs_reference() const { return !material.isotropic(); }

      /// The frames and maps at the points of @p k's cell (built with
      /// update_flags() and, if needs_reference(), the reference mapping);
      /// nothing for an isotropic law.
      void reinit(const model::CellKinematics<dim> &k);
      /// The same from frames computed earlier (PointFrames::cell()), for
      /// @p n_points points.
      void reinit(const dealii::Tensor<2, 3> *cell_frames,
                  const unsigned int          n_points);

      /// Hill's map at point q; nullptr for an isotropic law.
      const Mandel6x6 *map(const unsigned int q) const
      {
        return material.isotropic() ? nullptr : &maps[q];
      }
      /// Columns RD, TD, ND at point q.
      const dealii::Tensor<2, 3> &frame(const unsigned int q) const
      {
        return frames[q];
      }

    private:
      const RigidViscoplastic          &material;
      const model::MaterialFrame<dim>   initial;
      std::vector<dealii::Tensor<2, 3>> frames;
      std::vector<Mandel6x6>            maps;
    };
  } // namespace material
} // namespace formsolve
