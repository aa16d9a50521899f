#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/solver/mumps_direct.h>
#include <formsolve/solver/nested_dissection.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Export.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <dmumps_c.h>
#include <smumps_c.h>

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

    namespace
    {
      /// MUMPS's structure and entry point of one precision.
      template <typename Real>
      struct Precision;
      template <>
      struct Precision<double>
      {
        using Structure = DMUMPS_STRUC_C;
        static void run(Structure &id) { dmumps_c(&id); }
      };
      template <>
      struct Precision<float>
      {
        using Structure = SMUMPS_STRUC_C;
        static void run(Structure &id) { smumps_c(&id); }
      };
    } // namespace

    struct MumpsDirect::Data
    {
      virtual ~Data()                                                 = default;
      virtual void   analyse(const TrilinosWrappers::SparseMatrix &A) = 0;
      virtual void   factorise(const TrilinosWrappers::SparseMatrix &A) = 0;
      virtual void   solve(TrilinosWrappers::MPI::Vector       &x,
                           const TrilinosWrappers::MPI::Vector &b)      = 0;
      virtual double memory_mb() const                                  = 0;
      virtual double factor_entries() const                             = 0;
    };

    template <typename Real>
    class MumpsDirect::Instance : public MumpsDirect::Data
    {
    public:
      Instance(const MPI_Comm comm, const Settings &settings);
      ~Instance() override;
      void   analyse(const TrilinosWrappers::SparseMatrix &A) override;
      void   factorise(const TrilinosWrappers::SparseMatrix &A) override;
      void   solve(TrilinosWrappers::MPI::Vector       &x,
                   const TrilinosWrappers::MPI::Vector &b) override;
      double memory_mb() const override;
      double factor_entries() const override;

    private:
      const Settings                      settings;
      typename Precision<Real>::Structure id;
      MPI_Comm                            comm;
      bool                                root = false;
      /// Input triangle (global, 1-based) and values, in row-view order.
      std::vector<int>  irn, jcn;
      std::vector<Real> values;
      /// Per row-view entry of the local matrix: kept in the input.
      std::vector<bool> kept;
      /// symmetric_part: per input entry, the local row and the position in
      /// its row view of the transposed entry; -1 if not on this rank (or
      /// on the diagonal).
      std::vector<int> mirror_row, mirror_position;
      /// Pivot order (root, 1-based).
      std::vector<int> pivot_position;
      /// Global index of each local row (0-based; 1-based for MUMPS's
      /// distributed right-hand side) and that right-hand side.
      std::vector<int>  local_rows, rhs_rows;
      std::vector<Real> rhs;
      /// The distributed solution: the unknowns this rank eliminated
      /// (ISOL_loc, 1-based), their values, and the export to the vector's
      /// rows, rebuilt when a solve returns other rows on any rank.
      std::vector<int>               solution_rows, exported_rows;
      std::vector<Real>              solution;
      std::unique_ptr<Epetra_Map>    solution_map;
      std::unique_ptr<Epetra_Export> to_owner;

      /// Copies the values of @p A's stored entries (the triangle kept at
      /// analysis) into the MUMPS input, averaged with their transposes when
      /// symmetric_part is set.
      void copy_values(const TrilinosWrappers::SparseMatrix &A);
      /// symmetric_part: where each input entry's transpose is stored.
      void find_mirrors(const TrilinosWrappers::SparseMatrix &A);
      /// One MUMPS call (JOB = @p job), then check(@p what).
      void call(const int job, const char *what);
      /// Throws if MUMPS's last call failed (INFOG(1) < 0; the same on all
      /// ranks).
      void check(const char *what) const;
    };

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
      data->solve(x, b);
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
      Precision<Real>::run(id);
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
      id.job = -2;
      Precision<Real>::run(id);
    }

    template <typename Real>
    void MumpsDirect::Instance<Real>::call(const int job, const char *what)
    {
      id.job = job;
      Precision<Real>::run(id);
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
      rhs.resize(local_rows.size());

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
          Precision<Real>::run(id);
          const bool workspace = INFOG(1) == -8 || INFOG(1) == -9 ||
                                 INFOG(1) == -14 || INFOG(1) == -15 ||
                                 INFOG(1) == -17 || INFOG(1) == -20;
          if (!workspace || attempt == 4)
            break;
          ICNTL(14) = 2 * std::max(ICNTL(14), 20);
        }
      check("numeric factorisation");
      // INFO(23): the unknowns this rank eliminated; its share of every
      // solution comes back there, which may differ after a factorisation
      // (delayed pivots).
      const int n_pivots = id.info[22];
      solution_rows.assign(n_pivots, 0);
      solution.assign(n_pivots, 0);
      id.lsol_loc = n_pivots;
      id.isol_loc = solution_rows.data();
      id.sol_loc  = solution.data();
    }

    template <typename Real>
    void
    MumpsDirect::Instance<Real>::solve(TrilinosWrappers::MPI::Vector       &x,
                                       const TrilinosWrappers::MPI::Vector &b)
    {
      const double *source = b.trilinos_vector()[0];
      std::copy(source, source + rhs.size(), rhs.begin());
      id.nloc_rhs = rhs.size();
      id.lrhs_loc = rhs.size();
      id.irhs_loc = rhs_rows.data();
      id.rhs_loc  = rhs.data();
      id.nrhs     = 1;
      id.lrhs     = id.n;
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
          const Epetra_BlockMap &target = x.trilinos_vector().Map();
          solution_map                  = std::make_unique<Epetra_Map>(-1,
                                                      rows.size(),
                                                      rows.data(),
                                                      0,
                                                      target.Comm());
          to_owner = std::make_unique<Epetra_Export>(*solution_map, target);
        }
      Epetra_Vector values(*solution_map);
      std::copy(solution.begin(), solution.end(), values.Values());
      AssertThrow(x.trilinos_vector().Export(values, *to_owner, Insert) == 0,
                  ExcMessage("MUMPS: the export of the solution failed"));
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
    template class MumpsDirect::Instance<double>;
    template class MumpsDirect::Instance<float>;
  } // namespace solver
} // namespace formsolve
