// Where each entry of a cell's tangent lands in the rows of the filled
// Trilinos matrix, found once per mesh. The tangent assembly then adds a cell
// matrix by position, without the index searches that
// AffineConstraints::distribute_local_to_global and Epetra's
// SumIntoGlobalValues make for every entry (a third of the assembly time at
// 66k DoFs; doc/performance.md, "Assembly by position"). Cells with a
// constrained DoF, a DoF owned by another rank, or a row too long for the
// byte offsets are not mapped: they keep the general path, so the sums are
// the same, entry by entry and in the same order.
#pragma once
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cstdint>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class CellScatter
    {
    public:
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

      /// Maps the locally owned cells of @p dof_handler into @p matrix, whose
      /// sparsity pattern must be final (filled).
      void reinit(const dealii::DoFHandler<dim>           &dof_handler,
                  const dealii::AffineConstraints<double> &constraints,
                  const MatrixType                        &matrix);

      /// Whether the cell with this active cell index is mapped.
      bool maps(const unsigned int active_cell_index) const
      {
        return active_cell_index < slot.size() &&
               slot[active_cell_index] != invalid;
      }

      /// Adds @p K of a mapped cell to @p matrix (the matrix of reinit() or
      /// a copy of it with the same pattern).
      void add(const unsigned int                active_cell_index,
               const dealii::FullMatrix<double> &K,
               MatrixType                       &matrix) const;

      unsigned int n_mapped_cells() const { return n_mapped; }

      std::size_t memory_consumption() const;

    private:
      static constexpr unsigned int invalid = ~0u;

      unsigned int              n         = 0; // DoFs per cell
      unsigned int              n_mapped  = 0;
      long long                 n_entries = -1; // of the mapped pattern
      std::vector<unsigned int> slot;           // per active cell
      std::vector<int>          rows;           // n local rows per slot
      std::vector<std::uint8_t> offsets;        // n * n positions in the rows
    };
  } // namespace solver
} // namespace formsolve
