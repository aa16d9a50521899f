// MumpsSolver with two right-hand sides on one matrix: the body correction
// and the blank holder's column of the bordered system (doc/theory.md
// section 6a). A substitution reads the whole factor from memory, and that
// is most of its cost: with MUMPS both GMRES solves run side by side and
// each application of the factors serves both right-hand sides.
#include <formsolve/linear/flexible_gmres.h>
#include <formsolve/linear/mumps_solver.h>

#include <algorithm>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    unsigned int MumpsSolver::solve_pair(const Matrix &A,
                                         Vector       &x,
                                         const Vector &b,
                                         Vector       &y,
                                         const Vector &c,
                                         const bool    may_reuse)
    {
      try_reuse   = may_reuse;
      last_matrix = &A;
      // The same decisions as solve() makes for each of the
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

    unsigned int MumpsSolver::apply_current_factors(Vector       &x,
                                                    const Vector &b,
                                                    Vector       &y,
                                                    const Vector &c)
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

    unsigned int
    MumpsSolver::gmres_pair_with_factors(const Matrix      &A,
                                         Vector            &x,
                                         const Vector      &b,
                                         Vector            &y,
                                         const Vector      &c,
                                         const unsigned int max_iterations,
                                         bool (&converged)[2])
    {
      // As gmres_with_factors(), for both.
      const double relative = std::max(prm.reuse_tolerance, forcing);
      const auto   results  = flexible_gmres_pair(
        [&A](Vector &dst, const Vector &src) { A.vmult(dst, src); },
        [this](Vector &dst, const Vector &src) { substitute(dst, src); },
        [this](Vector       &dst0,
               const Vector &src0,
               Vector       &dst1,
               const Vector &src1) { substitute(dst0, src0, dst1, src1); },
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
