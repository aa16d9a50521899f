#include <deal.II/base/exceptions.h>

#include <formsolve/forming/cell_scatter.h>
#include <formsolve/model/dimensions.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    void CellScatter<dim>::reinit(const DoFHandler<dim>           &dof_handler,
                                  const AffineConstraints<double> &constraints,
                                  const MatrixType                &matrix)
    {
      const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
      Assert(A.Filled(), ExcMessage("The pattern must be final."));
      n = dof_handler.get_fe().n_dofs_per_cell();
      slot.assign(dof_handler.get_triangulation().n_active_cells(), invalid);
      // Room for every owned cell at once: growing by doubling would hold
      // the old and the new arrays together (1.5-2x the map at its peak).
      std::size_t owned = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        owned += cell->is_locally_owned();
      rows.clear();
      offsets.clear();
      rows.reserve(owned * n);
      offsets.reserve(owned * n * n);
      n_mapped  = 0;
      n_entries = A.NumMyNonzeros();

      std::vector<types::global_dof_index> dofs(n);
      std::vector<int>                     r(n), c(n);
      std::vector<std::uint8_t>            o(n * n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          cell->get_dof_indices(dofs);
          bool ok = true;
          for (unsigned int i = 0; i < n && ok; ++i)
            {
              r[i] = A.RowMap().LID(
                static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
              c[i] = A.ColMap().LID(
                static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
              ok =
                r[i] >= 0 && c[i] >= 0 && !constraints.is_constrained(dofs[i]);
            }
          for (unsigned int i = 0; i < n && ok; ++i)
            {
              int     length;
              double *values;
              int    *columns;
              A.ExtractMyRowView(r[i], length, values, columns);
              for (unsigned int j = 0; j < n && ok; ++j)
                {
                  const auto p = std::find(columns, columns + length, c[j]);
                  ok           = p != columns + length && p - columns < 256;
                  if (ok)
                    o[i * n + j] = static_cast<std::uint8_t>(p - columns);
                }
            }
          if (!ok)
            continue;
          slot[cell->active_cell_index()] = n_mapped++;
          rows.insert(rows.end(), r.begin(), r.end());
          offsets.insert(offsets.end(), o.begin(), o.end());
        }
    }

    template <int dim>
    void CellScatter<dim>::add(const unsigned int        active_cell_index,
                               const FullMatrix<double> &K,
                               MatrixType               &matrix) const
    {
      // The values are written through the row views of a const matrix:
      // deal.II gives no other access to Epetra's storage.
      const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
      Assert(A.NumMyNonzeros() == n_entries,
             ExcMessage("The matrix pattern changed since reinit()."));
      Assert(K.m() == n && K.n() == n, ExcDimensionMismatch(K.m(), n));
      const unsigned int  s = slot[active_cell_index];
      const int          *r = &rows[std::size_t(s) * n];
      const std::uint8_t *o = &offsets[std::size_t(s) * n * n];
      for (unsigned int i = 0; i < n; ++i)
        {
          int     length;
          double *values;
          int    *columns;
          A.ExtractMyRowView(r[i], length, values, columns);
          const double       *k  = &K(i, 0);
          const std::uint8_t *oi = o + i * n;
          for (unsigned int j = 0; j < n; ++j)
            values[oi[j]] += k[j];
        }
    }

    template <int dim>
    std::size_t CellScatter<dim>::memory_consumption() const
    {
      return slot.capacity() * sizeof(unsigned int) +
             rows.capacity() * sizeof(int) + offsets.capacity();
    }

#define INSTANTIATE(dim) template class CellScatter<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
