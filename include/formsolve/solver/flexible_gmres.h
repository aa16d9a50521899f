// Right-preconditioned flexible GMRES (Saad 1993) for the solves with stored
// factors (solver/linear_solver.cc). It keeps z_j = P^-1 v_j and forms
// x = x0 + sum_j y_j z_j, so that b - A x is the residual the iteration
// estimated, whatever P^-1 does to each vector (single-precision or older
// factors). deal.II 9.4's SolverGMRES forms x = x0 + P^-1 (V y) with one more
// application of P^-1: with single-precision factors that application alone
// leaves |b - A x| at 1e-3 |b| and more, far above the tolerance it reported
// (doc/performance.md, "Flexible GMRES"). Its SolverFGMRES tests convergence
// one column late, which costs one application per solve as well.
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace formsolve
{
  namespace solver
  {
    struct FlexibleGmresResult
    {
      /// Preconditioner applications (= Krylov columns) used.
      unsigned int iterations = 0;
      /// |b - A x| at return (the iteration's estimate, which is the true
      /// residual up to round-off in double precision).
      double residual  = 0;
      bool   converged = false;
    };

    /// Solves A x = b from the initial @p x until |b - A x| <= @p tolerance
    /// (absolute), within @p max_iterations preconditioner applications;
    /// restarts every @p max_basis columns. @p x holds the last iterate also
    /// when it does not converge.
    FlexibleGmresResult flexible_gmres(
      const std::function<void(dealii::TrilinosWrappers::MPI::Vector &,
                               const dealii::TrilinosWrappers::MPI::Vector &)>
        &operator_vmult,
      const std::function<void(dealii::TrilinosWrappers::MPI::Vector &,
                               const dealii::TrilinosWrappers::MPI::Vector &)>
                                                  &precondition,
      dealii::TrilinosWrappers::MPI::Vector       &x,
      const dealii::TrilinosWrappers::MPI::Vector &b,
      const double                                 tolerance,
      const unsigned int                           max_iterations,
      const unsigned int                           max_basis = 100);
  } // namespace solver
} // namespace formsolve
