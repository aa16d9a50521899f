// Diagnostics: a Lanczos estimate of a system matrix's condition number from
// a few unpreconditioned CG steps (Linear solver/Condition estimate
// iterations; history.csv column condition_estimate).
#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace formsolve
{
  namespace solver
  {
    /// cond(A) estimated from the Lanczos tridiagonal of @p iterations CG
    /// steps on A y = @p b (a lower bound, meaningful for symmetric A).
    double estimate_condition(const dealii::TrilinosWrappers::SparseMatrix &A,
                              const dealii::TrilinosWrappers::MPI::Vector  &b,
                              const unsigned int iterations);
  } // namespace solver
} // namespace formsolve
