// The state the forming leaves at the points of the release: the stress
// (the flow rule's deviator at the last step's rate of deformation and the
// stored mean stress), the equivalent plastic strain, the last equivalent
// strain rate and the yield metric in the current frame (doc/theory.md,
// section 12). History values live at the forming's Gauss points; they are
// carried to the release's points through the local polynomial they
// interpolate (FETools' quadrature projection).
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/release_law.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/state/state.h>

#include <vector>

namespace formsolve
{
  namespace springback
  {
    using dealii::SymmetricTensor;

    struct EndPoint
    {
      SymmetricTensor<2, 3> stress;     // MPa
      SymmetricTensor<4, 3> metric;     // the criterion's P, current frame
      double                strain = 0; // equivalent plastic strain (-)
      double                rate   = 0; // equivalent strain rate (1/s)
    };

    template <int dim>
    class EndState
    {
    public:
      /// At the points of @p quadrature on every locally owned cell, in
      /// the configuration of @p mapping.
      EndState(const state::State<dim>           &state,
               const dealii::Mapping<dim>        &mapping,
               const material::RigidViscoplastic &material,
               const material::ReleaseLaw        &law,
               const dealii::Quadrature<dim>     &quadrature);

      /// The points of a locally owned cell.
      const std::vector<EndPoint> &
      at(const typename dealii::Triangulation<dim>::active_cell_iterator &cell)
        const
      {
        return points[cell->active_cell_index()];
      }

    private:
      std::vector<std::vector<EndPoint>> points; // by active cell index
    };
  } // namespace springback
} // namespace formsolve
