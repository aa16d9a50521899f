// Adds the nodal contact forces and stiffnesses of a contact set to the
// system (doc/theory.md, eq. 9).
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/tools/tool_set.h>

#include <vector>

namespace formsolve
{
  namespace contact
  {
    /// r -= f_contact and K += -df/dv for the active (and locked) pairs with
    /// factors @p epsilon into @p matrix and @p residual where given; then
    /// compresses them. The stiffness is condensed with @p constraints
    /// without entries on constrained diagonals (the body's keep those rows
    /// regular).
    template <int dim>
    void add_contact_terms(const ContactSet<dim>                   &set,
                           const std::vector<double>               &epsilon,
                           const tools::ToolSet<dim>               &tools,
                           const double                             v0,
                           const double                             dt,
                           const bool                               newton,
                           const dealii::AffineConstraints<double> &constraints,
                           dealii::TrilinosWrappers::SparseMatrix  *matrix,
                           dealii::TrilinosWrappers::MPI::Vector   *residual);
  } // namespace contact
} // namespace formsolve
