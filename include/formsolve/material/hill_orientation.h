// Hill's map M = T(R) S at the quadrature points of one cell, with R the
// orthotropy frame turned with the sheet (model::MaterialFrame): what the
// point law needs besides the strain rate (RigidViscoplastic::evaluate).
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

      /// The frames and maps at the points of @p k's cell (built with
      /// update_jacobians and the reference mapping).
      void reinit(const model::CellKinematics<dim> &k);

      const Mandel6x6 &map(const unsigned int q) const { return maps[q]; }
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
