// Implementation detail of MumpsDirect: one MUMPS instance of one
// precision (dmumps or smumps) with its input arrays, pivot order and
// distributed right-hand side. Included only by source/linear/mumps_direct.cc
// (set-up and analysis) and source/linear/mumps_numeric.cc (values,
// factorisation, solve).
#pragma once

#include <formsolve/linear/mumps_direct.h>

#include <Epetra_Export.h>
#include <Epetra_Map.h>
#include <dmumps_c.h>
#include <mpi.h>
#include <smumps_c.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    namespace mumps_detail
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
    } // namespace mumps_detail

    struct MumpsDirect::Data
    {
      virtual ~Data() = default;
      virtual void analyse(const dealii::TrilinosWrappers::SparseMatrix &A) = 0;
      virtual void
      factorise(const dealii::TrilinosWrappers::SparseMatrix &A) = 0;
      /// x[c] = A^-1 b[c] for every column c, in one MUMPS solve.
      virtual void
      solve(const std::vector<dealii::TrilinosWrappers::MPI::Vector *> &x,
            const std::vector<const dealii::TrilinosWrappers::MPI::Vector *>
              &b)                           = 0;
      virtual double memory_mb() const      = 0;
      virtual double factor_entries() const = 0;
    };

    template <typename Real>
    class MumpsDirect::Instance : public MumpsDirect::Data
    {
    public:
      Instance(const MPI_Comm comm, const Settings &settings);
      ~Instance() override;
      void analyse(const dealii::TrilinosWrappers::SparseMatrix &A) override;
      void factorise(const dealii::TrilinosWrappers::SparseMatrix &A) override;
      void
      solve(const std::vector<dealii::TrilinosWrappers::MPI::Vector *>       &x,
            const std::vector<const dealii::TrilinosWrappers::MPI::Vector *> &b)
        override;
      double memory_mb() const override;
      double factor_entries() const override;

    private:
      const Settings                                    settings;
      typename mumps_detail::Precision<Real>::Structure id;
      MPI_Comm                                          comm;
      bool                                              root = false;
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
      /// rows, rebuilt when a solve returns other rows on any rank. With
      /// several right-hand sides, column c starts at c times the larger of 1
      /// and the count of rows (MUMPS's leading dimensions).
      std::vector<int>               solution_rows, exported_rows;
      std::vector<Real>              solution;
      std::unique_ptr<Epetra_Map>    solution_map;
      std::unique_ptr<Epetra_Export> to_owner;

      /// Copies the values of @p A's stored entries (the triangle kept at
      /// analysis) into the MUMPS input, averaged with their transposes when
      /// symmetric_part is set.
      void copy_values(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// symmetric_part: where each input entry's transpose is stored.
      void find_mirrors(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// One MUMPS call (JOB = @p job), then check(@p what).
      void call(const int job, const char *what);
      /// Throws if MUMPS's last call failed (INFOG(1) < 0; the same on all
      /// ranks).
      void check(const char *what) const;
    };
  } // namespace solver
} // namespace formsolve
