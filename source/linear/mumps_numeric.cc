// MumpsDirect's numeric phases: the values into MUMPS's input, the
// factorisation, and the solve with distributed right-hand side and solution.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/linear/mumps_instance.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Export.h>
#include <Epetra_Vector.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    // MUMPS's control arrays are documented 1-based.
#define ICNTL(i) id.icntl[(i)-1]
#define INFOG(i) id.infog[(i)-1]

    template <typename Real>
    void MumpsDirect::Instance<Real>::copy_values(
      const TrilinosWrappers::SparseMatrix &A)
    {
      const Epetra_CrsMatrix &m = A.trilinos_matrix();
      std::size_t             e = 0, i = 0;
      for (int r = 0; r < m.NumMyRows(); ++r)
        {
          int     length;
          double *v;
          int    *columns;
          m.ExtractMyRowView(r, length, v, columns);
          for (int k = 0; k < length; ++k, ++e)
            {
              AssertThrow(e < kept.size(),
                          ExcMessage("MUMPS: the sparsity pattern changed "
                                     "since the analysis"));
              if (kept[e])
                values[i++] = v[k];
            }
        }
      AssertThrow(e == kept.size(),
                  ExcMessage("MUMPS: the sparsity pattern changed since the "
                             "analysis"));
      if (!settings.symmetric_part)
        return;
      for (std::size_t k = 0; k < values.size(); ++k)
        if (mirror_row[k] >= 0)
          {
            int     length;
            double *v;
            int    *columns;
            m.ExtractMyRowView(mirror_row[k], length, v, columns);
            values[k] = 0.5 * (values[k] + v[mirror_position[k]]);
          }
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::factorise(
      const TrilinosWrappers::SparseMatrix &A)
    {
      copy_values(A);
      // Too little workspace for the pivoting MUMPS met: more, and again.
      for (unsigned int attempt = 0;; ++attempt)
        {
          id.job = 2;
          mumps_detail::Precision<Real>::run(id);
          const bool workspace = INFOG(1) == -8 || INFOG(1) == -9 ||
                                 INFOG(1) == -14 || INFOG(1) == -15 ||
                                 INFOG(1) == -17 || INFOG(1) == -20;
          if (INFOG(1) < 0 && !workspace && ICNTL(8) == -1)
            {
              // Failed with the kept scaling: scale these values afresh.
              ICNTL(8) = 77;
              continue;
            }
          if (!workspace || attempt == 4)
            break;
          ICNTL(14) = 2 * std::max(ICNTL(14), 20);
        }
      check("numeric factorisation");
      // MUMPS's scaling (ICNTL(8) = 77: computed in every factorisation)
      // is kept from the first factorisation after the analysis, as MUMPS's
      // own value-based permutation is: the tangents of one mesh differ
      // little, and the scaling cost 7-16 % of each factorisation on the
      // shipped 3-D case (doc/performance.md, "MUMPS's scaling kept").
      if (ICNTL(8) != -1 && id.colsca_from_mumps && id.rowsca_from_mumps)
        ICNTL(8) = -1;
      // INFO(23): the unknowns this rank eliminated; its share of every
      // solution comes back there, which may differ after a factorisation
      // (delayed pivots).
      solution_rows.assign(id.info[22], 0);
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::solve(
      const std::vector<TrilinosWrappers::MPI::Vector *>       &x,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &b)
    {
      Assert(x.size() == b.size() && !x.empty(), ExcInternalError());
      const std::size_t n_columns = b.size();
      const std::size_t n_rows    = local_rows.size();
      const std::size_t rhs_lead  = std::max<std::size_t>(n_rows, 1);
      rhs.resize(rhs_lead * n_columns);
      for (std::size_t c = 0; c < n_columns; ++c)
        {
          const double *source = b[c]->trilinos_vector()[0];
          std::copy(source, source + n_rows, rhs.begin() + c * rhs_lead);
        }
      id.nloc_rhs                     = n_rows;
      id.lrhs_loc                     = rhs_lead;
      id.irhs_loc                     = rhs_rows.data();
      id.rhs_loc                      = rhs.data();
      id.nrhs                         = n_columns;
      id.lrhs                         = id.n;
      const std::size_t n_pivots      = solution_rows.size();
      const std::size_t solution_lead = std::max<std::size_t>(n_pivots, 1);
      solution.resize(solution_lead * n_columns);
      id.lsol_loc = solution_lead;
      id.isol_loc = solution_rows.data();
      id.sol_loc  = solution.data();
      call(3, "solve");
      // The export is rebuilt only when a factorisation moved the rows of
      // the solution on some rank.
      const bool changed =
        Utilities::MPI::logical_or(!to_owner || solution_rows != exported_rows,
                                   comm);
      if (changed)
        {
          exported_rows = solution_rows;
          std::vector<int> rows(solution_rows.size());
          for (std::size_t k = 0; k < rows.size(); ++k)
            rows[k] = solution_rows[k] - 1;
          const Epetra_BlockMap &target = x[0]->trilinos_vector().Map();
          solution_map                  = std::make_unique<Epetra_Map>(-1,
                                                      rows.size(),
                                                      rows.data(),
                                                      0,
                                                      target.Comm());
          to_owner = std::make_unique<Epetra_Export>(*solution_map, target);
        }
      Epetra_Vector values(*solution_map);
      for (std::size_t c = 0; c < n_columns; ++c)
        {
          const auto column = solution.begin() + c * solution_lead;
          std::copy(column, column + n_pivots, values.Values());
          AssertThrow(x[c]->trilinos_vector().Export(values,
                                                     *to_owner,
                                                     Insert) == 0,
                      ExcMessage("MUMPS: the export of the solution failed"));
        }
    }

    template <typename Real>
    double MumpsDirect::Instance<Real>::memory_mb() const
    {
      return INFOG(22);
    }

    template <typename Real>
    double MumpsDirect::Instance<Real>::factor_entries() const
    {
      // Negative: in millions. INFOG(35): after low-rank compression.
      const int entries =
        settings.low_rank_tolerance > 0 ? INFOG(35) : INFOG(29);
      return entries >= 0 ? entries : -1e6 * entries;
    }

#define INSTANTIATE(Real)                                         \
  template void MumpsDirect::Instance<Real>::copy_values(         \
    const TrilinosWrappers::SparseMatrix &);                      \
  template void MumpsDirect::Instance<Real>::factorise(           \
    const TrilinosWrappers::SparseMatrix &);                      \
  template void MumpsDirect::Instance<Real>::solve(               \
    const std::vector<TrilinosWrappers::MPI::Vector *> &,         \
    const std::vector<const TrilinosWrappers::MPI::Vector *> &);  \
  template double MumpsDirect::Instance<Real>::memory_mb() const; \
  template double MumpsDirect::Instance<Real>::factor_entries() const;
    INSTANTIATE(double)
    INSTANTIATE(float)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
