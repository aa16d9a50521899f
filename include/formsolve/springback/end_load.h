// The tools' forces at the end of forming as the release's load, on an
// element of the forming's degree or another (doc/theory.md, eq. 12c).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <formsolve/state/state.h>

namespace formsolve
{
  namespace springback
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// f / m with m the lumped volume of each of @p state's DoFs in the
    /// configuration of @p mapping (ghosted): a density whose integral
    /// against the forming's shape functions gives back f's resultant.
    template <int dim>
    VectorType force_density(const state::State<dim>    &state,
                             const dealii::Mapping<dim> &mapping,
                             const VectorType           &f);

    /// The forces @p f (on @p state's DoFs) as a load on @p dh (all cells,
    /// the same mesh), with @p constraints' rows zero: copied DoF by DoF
    /// when @p dh has the forming's element, else their density integrated
    /// against @p dh's shape functions.
    template <int dim>
    VectorType load_on(const dealii::DoFHandler<dim>           &dh,
                       const dealii::AffineConstraints<double> &constraints,
                       const state::State<dim>                 &state,
                       const dealii::Mapping<dim>              &mapping,
                       const VectorType                        &f);
  } // namespace springback
} // namespace formsolve
