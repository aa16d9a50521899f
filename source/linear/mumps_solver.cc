#include <formsolve/linear/flexible_gmres.h>
#include <formsolve/linear/mumps_solver.h>

#include <algorithm>
#include <cstdlib>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    std::unique_ptr<LinearSolver>
    create_linear_solver(const parameters::LinearSolver &p,
                         const bool                      symmetric)
    {
      return std::make_unique<MumpsSolver>(p, symmetric);
    }

    MumpsSolver::MumpsSolver(const parameters::LinearSolver &p, const bool sym)
        : prm(p)
        , symmetric(sym)
    {}

    double MumpsSolver::factorisation_memory_mb() const
    {
      return mumps ? mumps->memory_mb() : 0.;
    }

    double MumpsSolver::factor_entries() const
    {
      return mumps ? mumps->factor_entries() : 0.;
    }

    void MumpsSolver::release_factors()
    {
      mumps.reset();
      factorised_matrix = nullptr;
      factorised_nnz    = 0;
      factors_current   = false;
    }

    namespace
    {
      /// A timer section when a timer is given.
      std::unique_ptr<TimerOutput::Scope> phase(TimerOutput *timer,
                                                const char  *name)
      {
        return timer ? std::make_unique<TimerOutput::Scope>(*timer, name)
                     : nullptr;
      }
    } // namespace

    unsigned int MumpsSolver::solve(const Matrix &A,
                                    Vector       &x,
                                    const Vector &b,
                                    const bool    may_reuse)
    {
      try_reuse   = may_reuse;
      last_matrix = &A;
      if (has_factorised_pattern(A) && n_factorisations > 0 &&
          prm.reuse_iterations > 0 && try_reuse)
        {
          unsigned int its = 0;
          if (gmres_with_factors(A, x, b, prm.reuse_iterations, its))
            {
              factors_current = false;
              return its;
            }
          // The failed iterations count: they were paid for.
          x = 0;
          return prm.reuse_iterations + factorise_new(A, x, b);
        }
      return factorise_new(A, x, b);
    }

    bool MumpsSolver::has_factorised_pattern(const Matrix &A) const
    {
      return factorised_matrix == &A.trilinos_matrix() &&
             factorised_nnz == A.n_nonzero_elements();
    }

    void MumpsSolver::analyse_if_new(const Matrix &A)
    {
      if (has_factorised_pattern(A))
        return;
      const auto            t = phase(timer, "linear solve: analysis");
      MumpsDirect::Settings settings;
      settings.symmetric_part =
        !symmetric && prm.unsymmetric_factors ==
                        parameters::UnsymmetricFactors::symmetric_part;
      settings.symmetric =
        prm.symmetric_factorisation && (symmetric || settings.symmetric_part);
      settings.metis_order           = prm.metis_order;
      settings.refinement_steps      = prm.refinement_steps;
      settings.low_rank_tolerance    = prm.low_rank_tolerance;
      settings.out_of_core_directory = prm.out_of_core_directory;
      settings.single_precision =
        prm.factor_precision == parameters::FactorPrecision::single_precision;
      mumps.reset();
      mumps = std::make_unique<MumpsDirect>(A.get_mpi_communicator(), settings);
      mumps->analyse(A);
      factorised_matrix = &A.trilinos_matrix();
      factorised_nnz    = A.n_nonzero_elements();
    }

    unsigned int
    MumpsSolver::factorise_new(const Matrix &A, Vector &x, const Vector &b)
    {
      analyse_if_new(A);
      factorise_current();
      return apply_current_factors(x, b);
    }

    void MumpsSolver::factorise_current()
    {
      {
        const auto t = phase(timer, "linear solve: factorisation");
        mumps->factorise(*last_matrix);
      }
      ++n_factorisations;
      factors_current = true;
    }

    bool MumpsSolver::exact_factors() const
    {
      return prm.low_rank_tolerance == 0 && !mumps->factors_symmetric_part() &&
             !mumps->factors_single();
    }

    unsigned int MumpsSolver::approximate_factors_limit() const
    {
      // Low-rank, single-precision factors, or those of the symmetric part,
      // are approximate: GMRES makes the solve as exact as the reuse
      // tolerance asks.
      return (prm.low_rank_tolerance > 0 ? prm.low_rank_iterations : 0) +
             (mumps->factors_symmetric_part() ? symmetric_part_iterations : 0) +
             (mumps->factors_single() ? single_precision_iterations : 0);
    }

    void MumpsSolver::approximate_factors_failed(const unsigned int limit) const
    {
      // Which approximation failed, and the entries that would help.
      std::string which, remedy;
      const auto  name = [&](const bool used, const char *w, const char *r) {
        if (used)
          {
            which += w;
            remedy += remedy.empty() ? r : std::string("; ") + r;
          }
      };
      name(prm.low_rank_tolerance > 0,
           "low-rank ",
           "Low-rank iterations, or a lower Low-rank tolerance");
      name(mumps->factors_single(),
           "single-precision ",
           "Factor precision = double");
      name(mumps->factors_symmetric_part(),
           "symmetric-part ",
           "Unsymmetric tangent = LU");
      AssertThrow(false,
                  ExcMessage("Linear solver: GMRES with the " + which +
                             "factors did not reach Reuse tolerance within " +
                             std::to_string(limit) + " iterations (" + remedy +
                             ")"));
      std::abort(); // not reached: AssertThrow(false, ...) throws
    }

    unsigned int MumpsSolver::apply_current_factors(Vector &x, const Vector &b)
    {
      if (exact_factors())
        {
          substitute(x, b);
          return 1;
        }
      const unsigned int limit = approximate_factors_limit();
      x                        = 0;
      unsigned int its         = 0;
      if (!gmres_with_factors(*last_matrix, x, b, limit, its))
        approximate_factors_failed(limit);
      return its;
    }

    void MumpsSolver::substitute(Vector &x, const Vector &b)
    {
      const auto t = phase(timer, "linear solve: substitution");
      mumps->solve(x, b);
    }

    void MumpsSolver::substitute(Vector       &x,
                                 const Vector &b,
                                 Vector       &y,
                                 const Vector &c)
    {
      const auto t = phase(timer, "linear solve: substitution");
      mumps->solve(x, b, y, c);
    }

    bool MumpsSolver::gmres_with_factors(const Matrix      &A,
                                         Vector            &x,
                                         const Vector      &b,
                                         const unsigned int max_iterations,
                                         unsigned int      &iterations)
    {
      // The factors live in the solver, not in A: they stay
      // those of the matrix values at the last factorisation. Flexible
      // GMRES: x is built from the preconditioned vectors themselves, so the
      // residual tested is that of x (solver/flexible_gmres.h).
      const auto result = flexible_gmres(
        [&A](Vector &dst, const Vector &src) { A.vmult(dst, src); },
        [this](Vector &dst, const Vector &src) { substitute(dst, src); },
        x,
        b,
        std::max(prm.reuse_tolerance, forcing) * b.l2_norm(),
        max_iterations);
      iterations = result.iterations;
      return result.converged;
    }

  } // namespace solver
} // namespace formsolve
