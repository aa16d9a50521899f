// LinearSolver with two right-hand sides on one matrix: the body correction
// and the blank holder's column of the bordered system (doc/theory.md
// section 6a). A substitution reads the whole factor from memory, and that
// is most of its cost: with MUMPS both GMRES solves run side by side and
// each application of the factors serves both right-hand sides.
#include <formsolve/solver/flexible_gmres.h>
#include <formsolve/solver/linear_solver.h>

#include <algorithm>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    unsigned int
    LinearSolver::solve_pair(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b,
                             TrilinosWrappers::MPI::Vector        &y,
                             const TrilinosWrappers::MPI::Vector  &c,
                             const bool                            may_reuse)
    {
      if (prm.type != parameters::LinearSolverType::direct ||
          prm.direct_solver != parameters::DirectSolver::mumps)
        {
          const unsigned int its = solve(A, x, b, may_reuse);
          return its + solve_again(y, c);
        }
      estimate_condition(A, b);
      try_reuse   = may_reuse;
      last_matrix = &A;
      last_direct = true;
      // The same decisions as solve_direct() and solve_again() make for the
      // two solves one after the other: the stored factors first, if
      // allowed; a solve that fails on them gets the new factorisation.
      bool         left[2] = {true, true};
      unsigned int its     = 0;
      if (has_factorised_pattern(A) && n_factorisations > 0 &&
          prm.reuse_iterations > 0 && try_reuse)
        {
          bool converged[2];
          its = gmres_pair_with_factors(A,
                                        x,
                                        b,
                                        y,
                                        c,
                                        prm.reuse_iterations,
                                        converged);
          if (converged[0] && converged[1])
            {
              factors_current = false;
              return its;
            }
          left[0] = !converged[0];
          left[1] = !converged[1];
        }
      analyse_if_new(A);
      factorise_current();
      if (left[0] && left[1])
        return its + apply_current_factors(x, b, y, c);
      return its + (left[0] ? apply_current_factors(x, b)
                            : apply_current_factors(y, c));
    }

    unsigned int
    LinearSolver::apply_current_factors(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &b,
                                        TrilinosWrappers::MPI::Vector       &y,
                                        const TrilinosWrappers::MPI::Vector &c)
    {
      if (exact_factors())
        {
          substitute(x, b, y, c);
          return 2;
        }
      const unsigned int limit = approximate_factors_limit();
      x                        = 0;
      y                        = 0;
      bool               converged[2];
      const unsigned int its =
        gmres_pair_with_factors(*last_matrix, x, b, y, c, limit, converged);
      if (!converged[0] || !converged[1])
        approximate_factors_failed(limit);
      return its;
    }

    unsigned int LinearSolver::gmres_pair_with_factors(
      const TrilinosWrappers::SparseMatrix &A,
      TrilinosWrappers::MPI::Vector        &x,
      const TrilinosWrappers::MPI::Vector  &b,
      TrilinosWrappers::MPI::Vector        &y,
      const TrilinosWrappers::MPI::Vector  &c,
      const unsigned int                    max_iterations,
      bool (&converged)[2])
    {
      // As gmres_with_factors(), for both.
      const double relative = std::max(prm.reuse_tolerance, forcing);
      const auto   results  = flexible_gmres_pair(
        [&A](TrilinosWrappers::MPI::Vector       &dst,
             const TrilinosWrappers::MPI::Vector &src) { A.vmult(dst, src); },
        [this](TrilinosWrappers::MPI::Vector       &dst,
               const TrilinosWrappers::MPI::Vector &src) {
          substitute(dst, src);
        },
        [this](TrilinosWrappers::MPI::Vector       &dst0,
               const TrilinosWrappers::MPI::Vector &src0,
               TrilinosWrappers::MPI::Vector       &dst1,
               const TrilinosWrappers::MPI::Vector &src1) {
          substitute(dst0, src0, dst1, src1);
        },
        x,
        b,
        relative * b.l2_norm(),
        max_iterations,
        y,
        c,
        relative * c.l2_norm(),
        max_iterations);
      converged[0] = results[0].converged;
      converged[1] = results[1].converged;
      return results[0].iterations + results[1].iterations;
    }

  } // namespace solver
} // namespace formsolve
