// The linear solves of a step: K x = b, and K x = b with K y = c on one
// matrix (the body correction and the blank holder's column of the bordered
// system). One interface; the back end is MUMPS (solver/mumps_solver.h),
// the only one left after the others measured slower (doc/performance.md).
#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/parameters/solvers.h>

#include <memory>

namespace formsolve
{
  namespace solver
  {
    class LinearSolver
    {
    public:
      using Matrix = dealii::TrilinosWrappers::SparseMatrix;
      using Vector = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~LinearSolver() = default;

      /// Solves A x = b; returns the iteration count (1 for one
      /// substitution). Throws with a message when the solver fails. The
      /// solver may keep factors of A until release_factors() or its end;
      /// it refers to @p A meanwhile. @p may_reuse false: no attempt with
      /// earlier factors; A is factorised.
      virtual unsigned int solve(const Matrix &A,
                                 Vector       &x,
                                 const Vector &b,
                                 const bool    may_reuse = true) = 0;

      /// Solves A x = b and A y = c; the iterations of both.
      virtual unsigned int solve_pair(const Matrix &A,
                                      Vector       &x,
                                      const Vector &b,
                                      Vector       &y,
                                      const Vector &c,
                                      const bool    may_reuse = true) = 0;

      /// Inexact Newton: a solve that iterates may stop at this relative
      /// residual if it is above the solver's own tolerance (0: at that).
      virtual void set_forcing(const double tolerance) = 0;

      /// Time the solver's phases in @p timer (within the caller's "linear
      /// solve").
      virtual void time_phases(dealii::TimerOutput &timer) = 0;

      /// Numeric factorisations since construction.
      virtual unsigned long factorisations() const = 0;

      /// Frees the factors before a phase that needs memory of its own
      /// (checkpoint, output, remeshing).
      virtual void release_factors() = 0;

      /// Memory of the last factorisation on all ranks (MB).
      virtual double factorisation_memory_mb() const = 0;
      /// Entries of the last factors.
      virtual double factor_entries() const = 0;
    };

    /// The linear solver of Linear solver; @p symmetric: the matrices are
    /// symmetric (the solver may use LDL^T).
    std::unique_ptr<LinearSolver>
    create_linear_solver(const parameters::LinearSolver &p,
                         const bool                      symmetric);
  } // namespace solver
} // namespace formsolve
