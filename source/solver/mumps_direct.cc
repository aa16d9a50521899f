#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/solver/mumps_direct.h>
#include <formsolve/solver/nested_dissection.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    // MUMPS's control arrays are documented 1-based.
#define ICNTL(i) id.icntl[(i)-1]
#define INFOG(i) id.infog[(i)-1]

    struct MumpsDirect::Data
    {
      DMUMPS_STRUC_C id;
      MPI_Comm       comm;
      bool           root = false;
      /// Input triangle (global, 1-based) and values, in row-view order.
      std::vector<int>    irn, jcn;
      std::vector<double> values;
      /// Per row-view entry of the local matrix: kept in the input.
      std::vector<bool> kept;
      /// symmetric_part: per input entry, the local row and the position in
      /// its row view of the transposed entry; -1 if not on this rank (or
      /// on the diagonal).
      std::vector<int> mirror_row, mirror_position;
      /// Pivot order (root, 1-based).
      std::vector<int> pivot_position;
      /// Right-hand side gather: global index of each local row; on the
      /// root, counts, offsets and the indices of all ranks.
      std::vector<int>    local_rows, counts, offsets, all_rows;
      std::vector<double> rhs, buffer;
    };

    MumpsDirect::MumpsDirect(const MPI_Comm comm, const Settings &s)
        : data(std::make_unique<Data>())
        , settings(s)
    {
      auto &id   = data->id;
      data->comm = comm;
      data->root = Utilities::MPI::this_mpi_process(comm) == 0;
      id.job     = -1;
      id.par     = 1; // the host works too
      Assert(settings.symmetric || !settings.symmetric_part,
             ExcInternalError());
      id.sym          = settings.symmetric ? 2 : 0;
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
      dmumps_c(&id);
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

    MumpsDirect::~MumpsDirect()
    {
      data->id.job = -2;
      dmumps_c(&data->id);
    }

    void MumpsDirect::call(const int job, const char *what)
    {
      data->id.job = job;
      dmumps_c(&data->id);
      check(what);
    }

    void MumpsDirect::check(const char *what) const
    {
      const auto &id = data->id;
      AssertThrow(INFOG(1) >= 0,
                  ExcMessage(
                    std::string("MUMPS ") + what +
                    " failed: INFOG(1) = " + std::to_string(INFOG(1)) +
                    ", INFOG(2) = " + std::to_string(INFOG(2)) +
                    (INFOG(1) == -10 ? " (numerically singular matrix)" : "")));
    }

    void MumpsDirect::analyse(const TrilinosWrappers::SparseMatrix &A)
    {
      auto                   &d  = *data;
      auto                   &id = d.id;
      const Epetra_CrsMatrix &m  = A.trilinos_matrix();
      d.irn.clear();
      d.jcn.clear();
      d.kept.clear();
      d.local_rows.resize(m.NumMyRows());
      for (int r = 0; r < m.NumMyRows(); ++r)
        {
          int     length;
          double *v;
          int    *columns;
          m.ExtractMyRowView(r, length, v, columns);
          const int row   = m.RowMap().GID(r);
          d.local_rows[r] = row;
          for (int k = 0; k < length; ++k)
            {
              const int  column = m.ColMap().GID(columns[k]);
              const bool keep   = !settings.symmetric || column <= row;
              d.kept.push_back(keep);
              if (keep)
                {
                  d.irn.push_back(row + 1);
                  d.jcn.push_back(column + 1);
                }
            }
        }
      d.values.resize(d.irn.size());
      if (settings.symmetric_part)
        find_mirrors(A);
      id.n = m.NumGlobalRows();
      if (Utilities::MPI::n_mpi_processes(d.comm) == 1)
        {
          // One rank: centralised input, which lets MUMPS permute large
          // entries to the diagonal and scale (ICNTL(6), not available with
          // distributed input).
          ICNTL(18) = 0;
          id.nnz    = d.irn.size();
          id.irn    = d.irn.data();
          id.jcn    = d.jcn.data();
          id.a      = d.values.data();
        }
      else
        {
          id.nnz_loc = d.irn.size();
          id.irn_loc = d.irn.data();
          id.jcn_loc = d.jcn.data();
          id.a_loc   = d.values.data();
        }

      // Gathers of the right-hand side: row counts and indices per rank.
      const int n_ranks = Utilities::MPI::n_mpi_processes(d.comm);
      const int n_local = d.local_rows.size();
      d.counts.assign(n_ranks, 0);
      MPI_Gather(&n_local, 1, MPI_INT, d.counts.data(), 1, MPI_INT, 0, d.comm);
      d.offsets.assign(n_ranks + 1, 0);
      for (int p = 0; p < n_ranks; ++p)
        d.offsets[p + 1] = d.offsets[p] + d.counts[p];
      d.all_rows.resize(d.root ? id.n : 0);
      MPI_Gatherv(d.local_rows.data(),
                  n_local,
                  MPI_INT,
                  d.all_rows.data(),
                  d.counts.data(),
                  d.offsets.data(),
                  MPI_INT,
                  0,
                  d.comm);
      d.rhs.resize(d.root ? id.n : 0);
      d.buffer.resize(d.root ? id.n : 0);

      if (settings.metis_order)
        {
          // The pattern on the root (MUMPS gathers it there too, for its
          // sequential analysis); METIS on its graph.
          const int        n_entries = d.irn.size();
          std::vector<int> entry_counts(n_ranks), entry_offsets(n_ranks + 1);
          MPI_Gather(&n_entries,
                     1,
                     MPI_INT,
                     entry_counts.data(),
                     1,
                     MPI_INT,
                     0,
                     d.comm);
          for (int p = 0; p < n_ranks; ++p)
            entry_offsets[p + 1] = entry_offsets[p] + entry_counts[p];
          std::vector<int> rows(d.root ? entry_offsets[n_ranks] : 0),
            columns(rows.size());
          std::vector<int> local(d.irn.size());
          for (unsigned int which = 0; which < 2; ++which)
            {
              const auto &source = which == 0 ? d.irn : d.jcn;
              auto       &target = which == 0 ? rows : columns;
              for (std::size_t k = 0; k < source.size(); ++k)
                local[k] = source[k] - 1;
              MPI_Gatherv(local.data(),
                          n_entries,
                          MPI_INT,
                          target.data(),
                          entry_counts.data(),
                          entry_offsets.data(),
                          MPI_INT,
                          0,
                          d.comm);
            }
          // METIS runs on the root only: its failure must stop every rank
          // (the others would wait in MUMPS's analysis).
          std::string failure;
          if (d.root)
            try
              {
                d.pivot_position = nested_dissection(id.n, rows, columns);
                for (auto &p : d.pivot_position)
                  ++p;
                id.perm_in = d.pivot_position.data();
              }
            catch (const std::exception &e)
              {
                failure = e.what();
              }
          failure = Utilities::MPI::broadcast(d.comm, failure, 0);
          AssertThrow(failure.empty(),
                      ExcMessage("Linear solver/Ordering = METIS: " + failure));
        }
      call(1, "analysis");
    }

    void MumpsDirect::find_mirrors(const TrilinosWrappers::SparseMatrix &A)
    {
      auto                   &d = *data;
      const Epetra_CrsMatrix &m = A.trilinos_matrix();
      d.mirror_row.assign(d.irn.size(), -1);
      d.mirror_position.assign(d.irn.size(), -1);
      for (std::size_t i = 0; i < d.irn.size(); ++i)
        {
          const int row = d.irn[i] - 1, column = d.jcn[i] - 1;
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
                d.mirror_row[i]      = local;
                d.mirror_position[i] = k;
                break;
              }
        }
    }

    void MumpsDirect::copy_values(const TrilinosWrappers::SparseMatrix &A)
    {
      auto                   &d = *data;
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
              AssertThrow(e < d.kept.size(),
                          ExcMessage("MUMPS: the sparsity pattern changed "
                                     "since the analysis"));
              if (d.kept[e])
                d.values[i++] = v[k];
            }
        }
      AssertThrow(e == d.kept.size(),
                  ExcMessage("MUMPS: the sparsity pattern changed since the "
                             "analysis"));
      if (!settings.symmetric_part)
        return;
      for (std::size_t k = 0; k < d.values.size(); ++k)
        if (d.mirror_row[k] >= 0)
          {
            int     length;
            double *v;
            int    *columns;
            m.ExtractMyRowView(d.mirror_row[k], length, v, columns);
            d.values[k] = 0.5 * (d.values[k] + v[d.mirror_position[k]]);
          }
    }

    void MumpsDirect::factorise(const TrilinosWrappers::SparseMatrix &A)
    {
      copy_values(A);
      auto &id = data->id;
      // Too little workspace for the pivoting MUMPS met: more, and again.
      for (unsigned int attempt = 0;; ++attempt)
        {
          id.job = 2;
          dmumps_c(&id);
          const bool workspace = INFOG(1) == -8 || INFOG(1) == -9 ||
                                 INFOG(1) == -14 || INFOG(1) == -15 ||
                                 INFOG(1) == -17 || INFOG(1) == -20;
          if (!workspace || attempt == 4)
            break;
          ICNTL(14) = 2 * std::max(ICNTL(14), 20);
        }
      check("numeric factorisation");
    }

    void MumpsDirect::solve(TrilinosWrappers::MPI::Vector       &x,
                            const TrilinosWrappers::MPI::Vector &b)
    {
      auto         &d       = *data;
      auto         &id      = d.id;
      const int     n_local = d.local_rows.size();
      const double *source  = b.trilinos_vector()[0];
      MPI_Gatherv(source,
                  n_local,
                  MPI_DOUBLE,
                  d.buffer.data(),
                  d.counts.data(),
                  d.offsets.data(),
                  MPI_DOUBLE,
                  0,
                  d.comm);
      if (d.root)
        for (int k = 0; k < id.n; ++k)
          d.rhs[d.all_rows[k]] = d.buffer[k];
      id.rhs  = d.rhs.data();
      id.nrhs = 1;
      id.lrhs = id.n;
      call(3, "solve");
      if (d.root)
        for (int k = 0; k < id.n; ++k)
          d.buffer[k] = d.rhs[d.all_rows[k]];
      MPI_Scatterv(d.buffer.data(),
                   d.counts.data(),
                   d.offsets.data(),
                   MPI_DOUBLE,
                   x.trilinos_vector()[0],
                   n_local,
                   MPI_DOUBLE,
                   0,
                   d.comm);
    }

    double MumpsDirect::memory_mb() const
    {
      const auto &id = data->id;
      return INFOG(22);
    }

    double MumpsDirect::factor_entries() const
    {
      const auto &id = data->id;
      // Negative: in millions. INFOG(35): after low-rank compression.
      const int entries =
        settings.low_rank_tolerance > 0 ? INFOG(35) : INFOG(29);
      return entries >= 0 ? entries : -1e6 * entries;
    }
  } // namespace solver
} // namespace formsolve
