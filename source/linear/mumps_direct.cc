#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/linear/mumps_instance.h>
#include <formsolve/linear/nested_dissection.h>

#include <Epetra_CrsMatrix.h>
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

    MumpsDirect::MumpsDirect(const MPI_Comm comm, const Settings &s)
        : settings(s)
    {
      if (settings.single_precision)
        data = std::make_unique<Instance<float>>(comm, settings);
      else
        data = std::make_unique<Instance<double>>(comm, settings);
    }

    MumpsDirect::~MumpsDirect() = default;

    void MumpsDirect::analyse(const TrilinosWrappers::SparseMatrix &A)
    {
      data->analyse(A);
    }

    void MumpsDirect::factorise(const TrilinosWrappers::SparseMatrix &A)
    {
      data->factorise(A);
    }

    void MumpsDirect::solve(TrilinosWrappers::MPI::Vector       &x,
                            const TrilinosWrappers::MPI::Vector &b)
    {
      data->solve({&x}, {&b});
    }

    void MumpsDirect::solve(TrilinosWrappers::MPI::Vector       &x0,
                            const TrilinosWrappers::MPI::Vector &b0,
                            TrilinosWrappers::MPI::Vector       &x1,
                            const TrilinosWrappers::MPI::Vector &b1)
    {
      data->solve({&x0, &x1}, {&b0, &b1});
    }

    double MumpsDirect::memory_mb() const
    {
      return data->memory_mb();
    }

    double MumpsDirect::factor_entries() const
    {
      return data->factor_entries();
    }

    template <typename Real>
    MumpsDirect::Instance<Real>::Instance(const MPI_Comm c, const Settings &s)
        : settings(s)
        , id()
        , comm(c)
    {
      root   = Utilities::MPI::this_mpi_process(comm) == 0;
      id.job = -1;
      id.par = 1; // the host works too
      Assert(settings.symmetric || !settings.symmetric_part,
             ExcInternalError());
      id.sym          = settings.symmetric ? 2 : 0;
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
      mumps_detail::Precision<Real>::run(id);
      AssertThrow(INFOG(1) >= 0,
                  ExcMessage("MUMPS initialisation failed: INFOG(1) = " +
                             std::to_string(INFOG(1))));
      ICNTL(1)  = -1; // errors are reported through the exception below
      ICNTL(2)  = -1;
      ICNTL(3)  = -1;
      ICNTL(4)  = 0;
      ICNTL(5)  = 0; // assembled input ...
      ICNTL(18) = 3; // ... distributed: each rank gives its own rows
      ICNTL(28) = 1; // sequential analysis (no ParMETIS/PT-Scotch in MUMPS)
      ICNTL(7)  = settings.metis_order ? 1 : 7;
      ICNTL(10) = static_cast<int>(settings.refinement_steps);
      ICNTL(20) = 0; // dense right-hand side on the host
      ICNTL(21) = 0; // solution on the host
      if (settings.low_rank_tolerance > 0)
        {
          // Block low-rank factors, stored compressed and used so in the
          // solve; chosen at the analysis (clustering of the fronts). The
          // UCFS variant (compress before the update) with compressed
          // contribution blocks factorised faster than MUMPS's default
          // variant in an exploratory run at 187k DoFs.
          ICNTL(35)  = 2;
          ICNTL(36)  = 1;
          ICNTL(37)  = 1;
          id.cntl[6] = settings.low_rank_tolerance; // CNTL(7)
        }
      if (!settings.out_of_core_directory.empty())
        {
          // The factors, the bulk of MUMPS's memory, go to files that MUMPS
          // names uniquely per rank and deletes at JOB = -2; the working
          // memory of the fronts stays in core.
          ICNTL(22) = 1;
          std::snprintf(id.ooc_tmpdir,
                        sizeof(id.ooc_tmpdir),
                        "%s",
                        settings.out_of_core_directory.c_str());
          std::snprintf(id.ooc_prefix, sizeof(id.ooc_prefix), "formsolve");
        }
    }

    template <typename Real>
    MumpsDirect::Instance<Real>::~Instance()
    {
      // The scaling kept by factorise() (ICNTL(8) = -1) is MUMPS's own
      // allocation, but MUMPS frees the scaling only if it did not come from
      // the user (KEEP(52) != -1, set from ICNTL(8) in the factorisation).
      if (id.keep[51] == -1 && id.colsca_from_mumps && id.rowsca_from_mumps)
        id.keep[51] = 77;
      id.job = -2;
      mumps_detail::Precision<Real>::run(id);
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::call(const int job, const char *what)
    {
      id.job = job;
      mumps_detail::Precision<Real>::run(id);
      check(what);
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::check(const char *what) const
    {
      AssertThrow(INFOG(1) >= 0,
                  ExcMessage(
                    std::string("MUMPS ") + what +
                    " failed: INFOG(1) = " + std::to_string(INFOG(1)) +
                    ", INFOG(2) = " + std::to_string(INFOG(2)) +
                    (INFOG(1) == -10 ? " (numerically singular matrix)" : "")));
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::analyse(
      const TrilinosWrappers::SparseMatrix &A)
    {
      const Epetra_CrsMatrix &m = A.trilinos_matrix();
      irn.clear();
      jcn.clear();
      kept.clear();
      local_rows.resize(m.NumMyRows());
      for (int r = 0; r < m.NumMyRows(); ++r)
        {
          int     length;
          double *v;
          int    *columns;
          m.ExtractMyRowView(r, length, v, columns);
          const int row = m.RowMap().GID(r);
          local_rows[r] = row;
          for (int k = 0; k < length; ++k)
            {
              const int  column = m.ColMap().GID(columns[k]);
              const bool keep   = !settings.symmetric || column <= row;
              kept.push_back(keep);
              if (keep)
                {
                  irn.push_back(row + 1);
                  jcn.push_back(column + 1);
                }
            }
        }
      values.resize(irn.size());
      if (settings.symmetric_part)
        find_mirrors(A);
      id.n = m.NumGlobalRows();
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        {
          // One rank: centralised input, which lets MUMPS permute large
          // entries to the diagonal and scale (ICNTL(6), not available with
          // distributed input).
          ICNTL(18) = 0;
          id.nnz    = irn.size();
          id.irn    = irn.data();
          id.jcn    = jcn.data();
          id.a      = values.data();
        }
      else
        {
          id.nnz_loc = irn.size();
          id.irn_loc = irn.data();
          id.jcn_loc = jcn.data();
          id.a_loc   = values.data();
        }

      // Right-hand side and solution distributed (ICNTL(20) = 10,
      // ICNTL(21) = 1): no vector of the whole system passes through rank 0
      // in a solve.
      ICNTL(20) = 10;
      ICNTL(21) = 1;
      rhs_rows.resize(local_rows.size());
      for (std::size_t k = 0; k < local_rows.size(); ++k)
        rhs_rows[k] = local_rows[k] + 1;

      if (settings.metis_order)
        {
          pivot_position = gathered_nested_dissection(comm, id.n, irn, jcn);
          if (root)
            id.perm_in = pivot_position.data();
        }
      call(1, "analysis");
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::find_mirrors(
      const TrilinosWrappers::SparseMatrix &A)
    {
      const Epetra_CrsMatrix &m = A.trilinos_matrix();
      mirror_row.assign(irn.size(), -1);
      mirror_position.assign(irn.size(), -1);
      for (std::size_t i = 0; i < irn.size(); ++i)
        {
          const int row = irn[i] - 1, column = jcn[i] - 1;
          const int local = m.RowMap().LID(column);
          if (row == column || local < 0)
            continue;
          int     length;
          double *v;
          int    *columns;
          m.ExtractMyRowView(local, length, v, columns);
          for (int k = 0; k < length; ++k)
            if (m.ColMap().GID(columns[k]) == row)
              {
                mirror_row[i]      = local;
                mirror_position[i] = k;
                break;
              }
        }
    }

    // The members defined here; source/linear/mumps_numeric.cc has the rest.
    template class MumpsDirect::Instance<double>;
    template class MumpsDirect::Instance<float>;
  } // namespace solver
} // namespace formsolve
