// Direct (MUMPS called directly, Amesos MUMPS/KLU) or iterative (GMRES/CG +
// ML AMG) linear solves.
#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/parameters/parameters.h>
#include <formsolve/solver/mumps_direct.h>
#include <formsolve/solver/null_space.h>

#include <memory>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace formsolve
{
  namespace solver
  {
    class LinearSolver
    {
    public:
      /// @p constant_modes: the rigid translations per component, for AMG.
      /// @p symmetric: the matrices are symmetric (MUMPS may use LDL^T).
      LinearSolver(const parameters::LinearSolver       &p,
                   const std::vector<std::vector<bool>> &constant_modes,
                   const bool                            symmetric);
      ~LinearSolver();

      /// Solves A x = b; returns the iteration count (1 for direct solves).
      /// Throws with a message when the solver fails. Direct solves keep the
      /// symbolic factorisation (ordering) while the matrix object and its
      /// sparsity stay the same; only the numeric factorisation is redone.
      /// The solver refers to @p A until destroyed: destroy it first.
      /// @p may_reuse false: no attempt with earlier factors (Reuse
      /// factorisation iterations); a direct solve factorises A.
      unsigned int solve(const dealii::TrilinosWrappers::SparseMatrix &A,
                         dealii::TrilinosWrappers::MPI::Vector        &x,
                         const dealii::TrilinosWrappers::MPI::Vector  &b,
                         const bool may_reuse = true);

      /// Solves A x = b with the matrix of the last solve(): the direct
      /// solver reuses its factorisation (one more forward and back
      /// substitution), the iterative one its preconditioner.
      unsigned int solve_again(dealii::TrilinosWrappers::MPI::Vector       &x,
                               const dealii::TrilinosWrappers::MPI::Vector &b);

      /// Solves A x = b and A y = c (one matrix, two right-hand sides).
      /// With MUMPS the two solves run side by side: each application of
      /// the factors serves both right-hand sides in one pass over them.
      /// Otherwise solve(), then solve_again(). Returns the iterations of
      /// both; @p may_reuse as for solve().
      unsigned int solve_pair(const dealii::TrilinosWrappers::SparseMatrix &A,
                              dealii::TrilinosWrappers::MPI::Vector        &x,
                              const dealii::TrilinosWrappers::MPI::Vector  &b,
                              dealii::TrilinosWrappers::MPI::Vector        &y,
                              const dealii::TrilinosWrappers::MPI::Vector  &c,
                              const bool may_reuse = true);

      /// Inexact Newton: GMRES with factors stops at this relative residual
      /// if it is above Reuse tolerance (0: at Reuse tolerance).
      void set_forcing(const double tolerance) { forcing = tolerance; }

      /// Time the direct solver's phases in @p timer: sections "linear
      /// solve: analysis", "...: factorisation", "...: substitution" (within
      /// the caller's "linear solve").
      void time_phases(dealii::TimerOutput &t) { timer = &t; }

      /// Numeric factorisations since construction (direct solver, and the
      /// iterative solver's fallbacks).
      unsigned long factorisations() const { return n_factorisations; }

      /// Whether solve() needs set_null_space() first (AMG with rigid-body
      /// modes, or with the line smoother, which needs the coordinates).
      bool needs_null_space() const
      {
        return prm.type == parameters::LinearSolverType::iterative &&
               (prm.amg_null_space ==
                  parameters::AmgNullSpace::rigid_body_modes ||
                prm.amg_smoother == parameters::AmgSmoother::line_gauss_seidel);
      }
      /// The near null space and node coordinates for the next AMG set-up
      /// (the old preconditioner, which may point to the old ones, goes).
      void set_null_space(NullSpace &&space)
      {
        amg.reset();
        null_space = std::move(space);
      }

      /// Frees the factors before a phase that needs memory of its own
      /// (checkpoint, output, remeshing). MUMPS 5.5 cannot free the factors
      /// and keep the analysis (it refuses JOB = -4): the next solve
      /// analyses again.
      void release_factors();

      /// Memory of the last MUMPS factorisation on all ranks (MB); 0 for the
      /// Amesos solvers.
      double factorisation_memory_mb() const;
      /// Entries of the last MUMPS factors (LDL^T: one triangle); 0 for the
      /// Amesos solvers.
      double factor_entries() const;

      /// Lanczos estimate of cond(A) from the last solve ('Condition estimate
      /// iterations' CG steps without preconditioner), 0 if off.
      double condition_estimate() const { return last_condition; }

    private:
      parameters::LinearSolver              prm;
      std::vector<std::vector<bool>>        constant_modes;
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    direct;
      std::unique_ptr<MumpsDirect>          mumps;
      const bool                            symmetric;
      dealii::TimerOutput                  *timer = nullptr;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
      const dealii::TrilinosWrappers::SparseMatrix *last_matrix       = nullptr;
      const void                                   *factorised_matrix = nullptr;
      unsigned long long                            factorised_nnz    = 0;
      double                                        last_condition    = 0;
      unsigned long                                 n_factorisations  = 0;
      NullSpace                                     null_space;
      /// set_forcing()'s relative residual.
      double forcing = 0;
      /// solve()'s may_reuse.
      bool try_reuse = true;
      /// The last solve was direct (its factors serve solve_again()).
      bool last_direct = true;
      /// The factorisation is that of last_matrix's current values (else it
      /// is an older one, used as a preconditioner).
      bool factors_current = false;

      /// GMRES on @p A preconditioned by the stored factorisation (an older
      /// one, or low-rank factors), to the reuse tolerance; false if it does
      /// not converge within @p max_iterations.
      bool gmres_with_factors(const dealii::TrilinosWrappers::SparseMatrix &A,
                              dealii::TrilinosWrappers::MPI::Vector        &x,
                              const dealii::TrilinosWrappers::MPI::Vector  &b,
                              const unsigned int max_iterations,
                              unsigned int      &iterations);
      /// GMRES as gmres_with_factors() for A x = b and A y = c side by side,
      /// within @p max_iterations each; whether each converged goes to
      /// @p converged, the iterations of both are returned.
      unsigned int
      gmres_pair_with_factors(const dealii::TrilinosWrappers::SparseMatrix &A,
                              dealii::TrilinosWrappers::MPI::Vector        &x,
                              const dealii::TrilinosWrappers::MPI::Vector  &b,
                              dealii::TrilinosWrappers::MPI::Vector        &y,
                              const dealii::TrilinosWrappers::MPI::Vector  &c,
                              const unsigned int max_iterations,
                              bool (&converged)[2]);
      /// x = A^-1 b with the factors of A's current values: one substitution,
      /// or GMRES when they are low-rank; returns the iterations.
      unsigned int
      apply_current_factors(dealii::TrilinosWrappers::MPI::Vector       &x,
                            const dealii::TrilinosWrappers::MPI::Vector &b);
      /// apply_current_factors() to A x = b and A y = c side by side.
      unsigned int
      apply_current_factors(dealii::TrilinosWrappers::MPI::Vector       &x,
                            const dealii::TrilinosWrappers::MPI::Vector &b,
                            dealii::TrilinosWrappers::MPI::Vector       &y,
                            const dealii::TrilinosWrappers::MPI::Vector &c);
      /// The factors are those of the matrix, in double precision: one
      /// substitution solves.
      bool exact_factors() const;
      /// How many GMRES iterations the current approximate factors may take
      /// to the tolerance.
      unsigned int approximate_factors_limit() const;
      /// Throws the message for GMRES that failed with approximate factors
      /// within @p limit iterations.
      [[noreturn]] void
      approximate_factors_failed(const unsigned int limit) const;
      /// Numeric factorisation of the last matrix's current values.
      void factorise_current();
      /// The analysis of @p A's pattern unless it is the factorised one.
      void analyse_if_new(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// Numeric factorisation of the operator's current values, then
      /// apply_current_factors().
      unsigned int
      factorise_and_substitute(dealii::TrilinosWrappers::MPI::Vector       &x,
                               const dealii::TrilinosWrappers::MPI::Vector &b);
      /// One forward and back substitution with the stored factorisation.
      void substitute(dealii::TrilinosWrappers::MPI::Vector       &x,
                      const dealii::TrilinosWrappers::MPI::Vector &b);
      /// The same for two right-hand sides (MUMPS: in one solve).
      void substitute(dealii::TrilinosWrappers::MPI::Vector       &x,
                      const dealii::TrilinosWrappers::MPI::Vector &b,
                      dealii::TrilinosWrappers::MPI::Vector       &y,
                      const dealii::TrilinosWrappers::MPI::Vector &c);

      unsigned int solve_direct(const dealii::TrilinosWrappers::SparseMatrix &A,
                                dealii::TrilinosWrappers::MPI::Vector        &x,
                                const dealii::TrilinosWrappers::MPI::Vector &b);
      /// A is the analysed matrix object with its sparsity unchanged.
      bool has_factorised_pattern(
        const dealii::TrilinosWrappers::SparseMatrix &A) const;
      /// The direct solve with A factorised (analysed first if its pattern
      /// is new).
      unsigned int
      factorise_new(const dealii::TrilinosWrappers::SparseMatrix &A,
                    dealii::TrilinosWrappers::MPI::Vector        &x,
                    const dealii::TrilinosWrappers::MPI::Vector  &b);
      /// ML on @p A with the null space and smoother of the parameters.
      void initialise_amg(const dealii::TrilinosWrappers::SparseMatrix &A);
      /// The iterative solve; if it does not converge, the direct one (or an
      /// exception with Fallback to direct = false).
      unsigned int
      iterate_or_fall_back(const dealii::TrilinosWrappers::SparseMatrix &A,
                           dealii::TrilinosWrappers::MPI::Vector        &x,
                           const dealii::TrilinosWrappers::MPI::Vector  &b);
      unsigned int iterate(const dealii::TrilinosWrappers::SparseMatrix &A,
                           dealii::TrilinosWrappers::MPI::Vector        &x,
                           const dealii::TrilinosWrappers::MPI::Vector  &b);

      void estimate_condition(const dealii::TrilinosWrappers::SparseMatrix &A,
                              const dealii::TrilinosWrappers::MPI::Vector  &b);
    };
  } // namespace solver
} // namespace formsolve
