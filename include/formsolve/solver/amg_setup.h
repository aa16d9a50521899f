// ML algebraic multigrid for the iterative linear solver
// (solver/linear_solver.h): deal.II's elliptic defaults with the near null
// space and smoother that Linear solver/... selects.
#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <formsolve/parameters/parameters.h>
#include <formsolve/solver/null_space.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    /// ML on @p A. @p constant_modes: the rigid translations per component;
    /// @p null_space: the rigid-body modes and node coordinates, which ML
    /// reads while it sets up (@p with_null_space: they must be there).
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG>
    make_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
             const parameters::LinearSolver               &prm,
             const std::vector<std::vector<bool>>         &constant_modes,
             NullSpace                                    &null_space,
             const bool                                    with_null_space);
  } // namespace solver
} // namespace formsolve
