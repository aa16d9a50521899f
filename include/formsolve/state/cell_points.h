// What the assembly and the history update both need at a cell's points,
// set up once: the kinematics at the full (deviatoric) and reduced
// (volumetric) quadrature, the strain rates of the velocity, and the point
// frame of the law (none for an isotropic one).
#pragma once

#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/material/hill_orientation.h>
#include <formsolve/material/point_frames.h>
#include <formsolve/model/cell_kinematics.h>

#include <vector>

namespace formsolve
{
  namespace state
  {
    template <int dim>
    class CellPoints
    {
    public:
      using CellIterator =
        typename dealii::DoFHandler<dim>::active_cell_iterator;

      /// @p extra: what the caller needs at the full points besides the
      /// frame's own flags. With @p frames (computed at @p full in this
      /// configuration) the point frames are read from it instead of being
      /// computed from the deformation gradient.
      CellPoints(const material::RigidViscoplastic &material,
                 const model::Kinematics<dim>      &kinematics,
                 const dealii::Mapping<dim>        &mapping,
                 const dealii::Mapping<dim>        &reference_mapping,
                 const dealii::FiniteElement<dim>  &fe,
                 const dealii::Quadrature<dim>     &full,
                 const dealii::Quadrature<dim>     &reduced,
                 const dealii::UpdateFlags          extra,
                 const material::PointFrames<dim>  *frames = nullptr);

      /// Both quadratures and the frame at @p cell, and the strain rates of
      /// @p v at the full points.
      void reinit(const CellIterator                          &cell,
                  const dealii::TrilinosWrappers::MPI::Vector &v);

      /// The one cell loop of the assembly and the history update: on each
      /// locally owned cell, reinit(cell, v), then @p work(cell, h) with h
      /// the cell's point histories in @p history.
      template <class History, class Work>
      void for_each_owned(const dealii::DoFHandler<dim>               &dofs,
                          const dealii::TrilinosWrappers::MPI::Vector &v,
                          History                                     &history,
                          const Work                                  &work)
      {
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              reinit(cell, v);
              work(cell, history.get_data(cell));
            }
      }

      model::CellKinematics<dim> &full() { return kf; }
      model::CellKinematics<dim> &reduced() { return kr; }
      /// The rate of deformation at full point q.
      const dealii::SymmetricTensor<2, 3> &rate(const unsigned int q) const
      {
        return D[q];
      }
      /// The law's map at full point q (nullptr: isotropic).
      const material::Mandel6x6 *map(const unsigned int q) const
      {
        return frame.map(q);
      }

      /// The orthotropy frame at full point q (columns RD, TD, ND); the
      /// identity for an isotropic law, which has none.
      dealii::Tensor<2, 3> axes(const unsigned int q) const
      {
        return frame.map(q)
                 ? frame.frame(q)
                 : dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
      }

    private:
      material::HillOrientation<dim>             frame;
      const material::PointFrames<dim>          *cached;
      model::CellKinematics<dim>                 kf, kr;
      std::vector<dealii::SymmetricTensor<2, 3>> D;
    };
  } // namespace state
} // namespace formsolve
