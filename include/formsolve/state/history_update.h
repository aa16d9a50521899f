// What a converged step leaves at the material points: equivalent strain,
// its rate, flow stress, mean stress, thickness strain and the damage
// integrals (doc/theory.md, section 7), and the volume-correction offsets an
// adaptation resets (eq. 5a).
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/material/damage.h>
#include <formsolve/material/point_frames.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/model/kinematics.h>
#include <formsolve/state/quadrature_history.h>

namespace formsolve
{
  namespace state
  {
    template <int dim>
    class HistoryUpdate
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// @p reference_mapping maps the initial configuration (the volume
      /// correction's dV0). With @p damage, advance() also integrates the
      /// damage criteria.
      HistoryUpdate(const material::RigidViscoplastic &material,
                    const model::Kinematics<dim>      &kinematics,
                    const dealii::Mapping<dim>        &reference_mapping,
                    const unsigned int                 degree,
                    const material::DamageCriteria    *damage = nullptr);

      /// After a converged step of @p dt at velocity @p v (ghosted), in the
      /// configuration of @p mapping (the start of the step): integrate
      /// strain, thickness strain and damage, store stresses. With
      /// @p frames, the point frames of that configuration (the step's).
      void advance(const dealii::DoFHandler<dim>    &dof_handler,
                   const dealii::Mapping<dim>       &mapping,
                   const VectorType                 &v,
                   const double                      dt,
                   HistoryStorage<dim>              &history,
                   const material::PointFrames<dim> *frames = nullptr) const;

      /// Swaps each cell's volume offset c and its volume error
      /// e = ln(dV/dV0) - c (cell means at the reduced points): before an
      /// adaptation the history carries e to the new cells, after it each
      /// new cell takes c = ln(dV/dV0) - e, so that the volume correction
      /// goes on from the error of the cells it came from (doc/theory.md,
      /// eq. 5a). Cells left alone get their c back.
      void exchange_volume_offsets(const dealii::DoFHandler<dim> &dof_handler,
                                   const dealii::Mapping<dim>    &mapping,
                                   HistoryStorage<dim> &history) const;

    private:
      /// One material point after a step of @p dt at rate @p D, with the
      /// mean stress @p mean_stress (MPa) and the sheet normal @p normal.
      void update_point(const dealii::Tensor<1, 3>          &normal,
                        const dealii::SymmetricTensor<2, 3> &D,
                        const double                         mean_stress,
                        const material::Mandel6x6           *map,
                        const double                         dt,
                        QuadraturePointHistory              &h) const;

      const material::RigidViscoplastic &material;
      const model::Kinematics<dim>      &kinematics;
      const dealii::Mapping<dim>        &reference_mapping;
      const material::DamageCriteria    *damage;
      const dealii::QGauss<dim>          full, reduced;
    };
  } // namespace state
} // namespace formsolve
