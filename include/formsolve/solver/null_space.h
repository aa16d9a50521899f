// The near null space of the velocity operator for algebraic multigrid:
// rigid translations and rotations of the current configuration, and the
// nodal coordinates ML needs to detect lines through the thickness for line
// smoothing (../shared/research/linear-solvers.md: translations alone are
// not enough on thin sheets).
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <vector>

namespace formsolve
{
  namespace solver
  {
    struct NullSpace
    {
      /// Velocity components per node: the owned DoFs come in blocks of
      /// this many (deal.II's numbering of an FESystem of FE_Q).
      unsigned int n_components = 0;
      /// Number of modes: dim translations and dim (dim - 1) / 2 rotations.
      unsigned int n_modes = 0;
      /// The modes on the owned DoFs, one after another (column-major, as
      /// ML reads "null space: vectors").
      std::vector<double> modes;
      /// x, y and z of the owned nodes, one array each (z = 0 in 2-D).
      std::vector<double> x, y, z;
    };

    /// Rigid-body modes of the sheet in the configuration of @p mapping,
    /// about the centroid of all nodes (the same point on every rank).
    template <int dim>
    NullSpace rigid_body_modes(const dealii::Mapping<dim>    &mapping,
                               const dealii::DoFHandler<dim> &dof_handler,
                               const dealii::IndexSet        &owned);
  } // namespace solver
} // namespace formsolve
