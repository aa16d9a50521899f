// MUMPS through its C interface, in the setting that suits formsolve's
// tangents: distributed assembled input straight from the Trilinos matrix's
// locally owned rows, symmetric LDL^T when the tangent is symmetric, a METIS
// nested-dissection pivot order, and the analysis kept while the sparsity
// pattern stays the same. Amesos cannot pass the lower triangle or a pivot
// order (../shared/research/linear-solvers.md). Right-hand side and
// solution stay distributed. Double (dmumps) or single precision (smumps)
// factors.
#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    class MumpsDirect
    {
    public:
      struct Settings
      {
        /// LDL^T of the lower triangle (the matrix must be symmetric, or
        /// symmetric_part be set).
        bool symmetric = false;
        /// With symmetric: factorise (A + A^T)/2, so that A may be
        /// unsymmetric; the factors are then approximate (a preconditioner).
        /// An entry whose transpose lies in another rank's rows keeps A's
        /// value.
        bool symmetric_part = false;
        /// METIS nested dissection; else MUMPS's automatic choice (PORD).
        bool metis_order = true;
        /// MUMPS ICNTL(10): at most this many steps of iterative
        /// refinement, stopped by MUMPS's backward-error test.
        unsigned int refinement_steps = 0;
        /// Block low-rank factorisation (MUMPS ICNTL(35) = 2) with this
        /// dropping tolerance (CNTL(7)); 0: full rank. The factors are then
        /// approximate: solve with them as a preconditioner.
        double low_rank_tolerance = 0;
        /// Out-of-core factors (MUMPS ICNTL(22) = 1): written to files in
        /// this directory by the factorisation and read back by every
        /// solve; empty: held in memory.
        std::string out_of_core_directory;
        /// Factors in single precision (MUMPS's smumps): half the memory and
        /// about half the factorisation time; the factors are then
        /// approximate (a preconditioner).
        bool single_precision = false;
      };

      MumpsDirect(const MPI_Comm comm, const Settings &settings);
      ~MumpsDirect();

      /// Analysis of @p A's sparsity pattern: pivot order and symbolic
      /// factorisation. Needed again only when the pattern changes.
      void analyse(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// Numeric factorisation of @p A's current values (same pattern as at
      /// analyse()). Throws with MUMPS's error code on failure.
      void factorise(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// x = A^-1 b with the stored factors.
      void solve(dealii::TrilinosWrappers::MPI::Vector       &x,
                 const dealii::TrilinosWrappers::MPI::Vector &b);
      /// x0 = A^-1 b0 and x1 = A^-1 b1 in one solve: one pass over the
      /// factors for both (the substitutions read the factors from memory,
      /// which is most of their cost).
      void solve(dealii::TrilinosWrappers::MPI::Vector       &x0,
                 const dealii::TrilinosWrappers::MPI::Vector &b0,
                 dealii::TrilinosWrappers::MPI::Vector       &x1,
                 const dealii::TrilinosWrappers::MPI::Vector &b1);

      /// The factors are those of the symmetric part, not of the matrix.
      bool factors_symmetric_part() const { return settings.symmetric_part; }
      /// The factors are in single precision.
      bool factors_single() const { return settings.single_precision; }

      /// Memory the last factorisation used on all ranks (MB, INFOG(22)).
      double memory_mb() const;
      /// Entries in the factors (INFOG(29); LDL^T stores one triangle;
      /// after low-rank compression INFOG(35)).
      double factor_entries() const;

    private:
      /// The MUMPS instance, of one precision (source/linear/mumps_direct.cc).
      struct Data;
      template <typename Real>
      class Instance;
      std::unique_ptr<Data> data;
      Settings              settings;
    };
  } // namespace solver
} // namespace formsolve
