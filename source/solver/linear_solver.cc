#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <formsolve/solver/amg_setup.h>
#include <formsolve/solver/flexible_gmres.h>
#include <formsolve/solver/linear_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

#include <algorithm>
#include <cstdlib>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    LinearSolver::LinearSolver(const parameters::LinearSolver       &p,
                               const std::vector<std::vector<bool>> &modes,
                               const bool                            sym)
        : prm(p)
        , constant_modes(modes)
        , symmetric(sym)
    {}

    double LinearSolver::factorisation_memory_mb() const
    {
      return mumps ? mumps->memory_mb() : 0.;
    }

    double LinearSolver::factor_entries() const
    {
      return mumps ? mumps->factor_entries() : 0.;
    }

    void LinearSolver::release_factors()
    {
      mumps.reset();
      direct.reset();
      problem.reset();
      factorised_matrix = nullptr;
      factorised_nnz    = 0;
      factors_current   = false;
    }

    LinearSolver::~LinearSolver() = default;

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

    void
    LinearSolver::estimate_condition(const TrilinosWrappers::SparseMatrix &A,
                                     const TrilinosWrappers::MPI::Vector  &b)
    {
      last_condition = 0;
      if (prm.condition_iterations == 0)
        return;
      // The Lanczos tridiagonal of CG gives the extreme eigenvalues; stop
      // after a fixed number of steps (convergence is not the point here).
      SolverControl control(prm.condition_iterations, 0., false, false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.connect_condition_number_slot(
        [this](const double c) { last_condition = c; },
        false);
      TrilinosWrappers::MPI::Vector y(b);
      y = 0;
      try
        {
          cg.solve(A, y, b, PreconditionIdentity());
        }
      catch (const SolverControl::NoConvergence &)
        {}
    }

    unsigned int LinearSolver::solve(const TrilinosWrappers::SparseMatrix &A,
                                     TrilinosWrappers::MPI::Vector        &x,
                                     const TrilinosWrappers::MPI::Vector  &b,
                                     const bool may_reuse)
    {
      estimate_condition(A, b);
      try_reuse   = may_reuse;
      last_matrix = &A;
      last_direct = prm.type == parameters::LinearSolverType::direct;
      if (last_direct)
        return solve_direct(A, x, b);
      initialise_amg(A);
      return iterate_or_fall_back(A, x, b);
    }

    bool LinearSolver::has_factorised_pattern(
      const TrilinosWrappers::SparseMatrix &A) const
    {
      return factorised_matrix == &A.trilinos_matrix() &&
             factorised_nnz == A.n_nonzero_elements();
    }

    unsigned int
    LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &A,
                               TrilinosWrappers::MPI::Vector        &x,
                               const TrilinosWrappers::MPI::Vector  &b)
    {
      const bool same_pattern = has_factorised_pattern(A);
      if (same_pattern && n_factorisations > 0 && prm.reuse_iterations > 0 &&
          try_reuse)
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

    void LinearSolver::analyse_if_new(const TrilinosWrappers::SparseMatrix &A)
    {
      if (has_factorised_pattern(A))
        return;
      auto      &matrix = const_cast<Epetra_CrsMatrix &>(A.trilinos_matrix());
      const auto t      = phase(timer, "linear solve: analysis");
      if (prm.direct_solver == parameters::DirectSolver::mumps)
        {
          MumpsDirect::Settings settings;
          settings.symmetric_part =
            !symmetric && prm.unsymmetric_factors ==
                            parameters::UnsymmetricFactors::symmetric_part;
          settings.symmetric = prm.symmetric_factorisation &&
                               (symmetric || settings.symmetric_part);
          settings.metis_order           = prm.metis_order;
          settings.refinement_steps      = prm.refinement_steps;
          settings.low_rank_tolerance    = prm.low_rank_tolerance;
          settings.out_of_core_directory = prm.out_of_core_directory;
          settings.single_precision =
            prm.factor_precision ==
            parameters::FactorPrecision::single_precision;
          mumps.reset();
          mumps =
            std::make_unique<MumpsDirect>(A.get_mpi_communicator(), settings);
          mumps->analyse(A);
        }
      else
        {
          problem = std::make_unique<Epetra_LinearProblem>();
          problem->SetOperator(&matrix);
          Amesos     factory;
          const bool amesos_mumps =
            prm.direct_solver == parameters::DirectSolver::amesos_mumps;
          direct.reset(
            factory.Create(amesos_mumps ? "Amesos_Mumps" : "Amesos_Klu",
                           *problem));
          AssertThrow(direct != nullptr,
                      ExcMessage("Linear solver/Direct solver: Amesos has no " +
                                 std::string(amesos_mumps ? "MUMPS" : "KLU")));
          AssertThrow(direct->SymbolicFactorization() == 0,
                      ExcMessage("symbolic factorisation failed"));
        }
      factorised_matrix = &matrix;
      factorised_nnz    = A.n_nonzero_elements();
    }

    unsigned int
    LinearSolver::factorise_new(const TrilinosWrappers::SparseMatrix &A,
                                TrilinosWrappers::MPI::Vector        &x,
                                const TrilinosWrappers::MPI::Vector  &b)
    {
      analyse_if_new(A);
      return factorise_and_substitute(x, b);
    }

    void LinearSolver::initialise_amg(const TrilinosWrappers::SparseMatrix &A)
    {
      const auto t = phase(timer, "linear solve: AMG set-up");
      amg = make_amg(A, prm, constant_modes, null_space, needs_null_space());
    }

    unsigned int
    LinearSolver::iterate_or_fall_back(const TrilinosWrappers::SparseMatrix &A,
                                       TrilinosWrappers::MPI::Vector        &x,
                                       const TrilinosWrappers::MPI::Vector  &b)
    {
      unsigned int failed_iterations = 0;
      try
        {
          return iterate(A, x, b);
        }
      catch (const SolverControl::NoConvergence &e)
        {
          failed_iterations = e.last_step;
          AssertThrow(prm.direct_fallback,
                      ExcMessage(
                        "Linear solver: the iterative solver did not reach "
                        "Tolerance within Max iterations = " +
                        std::to_string(prm.max_iterations) +
                        " (Fallback to direct = false)"));
        }
      // The count includes the iterations that failed: they were paid for.
      last_direct = true;
      x           = 0;
      return failed_iterations + solve_direct(A, x, b);
    }

    void LinearSolver::factorise_current()
    {
      {
        const auto t = phase(timer, "linear solve: factorisation");
        if (mumps)
          mumps->factorise(*last_matrix);
        else
          AssertThrow(direct->NumericFactorization() == 0,
                      ExcMessage(
                        "numeric factorisation failed (singular matrix?)"));
      }
      ++n_factorisations;
      factors_current = true;
    }

    unsigned int LinearSolver::factorise_and_substitute(
      TrilinosWrappers::MPI::Vector       &x,
      const TrilinosWrappers::MPI::Vector &b)
    {
      factorise_current();
      return apply_current_factors(x, b);
    }

    bool LinearSolver::exact_factors() const
    {
      return prm.low_rank_tolerance == 0 &&
             (mumps == nullptr ||
              (!mumps->factors_symmetric_part() && !mumps->factors_single()));
    }

    unsigned int LinearSolver::approximate_factors_limit() const
    {
      // Low-rank, single-precision factors, or those of the symmetric part,
      // are approximate: GMRES makes the solve as exact as the reuse
      // tolerance asks.
      const bool low_rank = prm.low_rank_tolerance > 0;
      const bool symmetric_part =
        mumps != nullptr && mumps->factors_symmetric_part();
      const bool single = mumps != nullptr && mumps->factors_single();
      return (low_rank ? prm.low_rank_iterations : 0) +
             (symmetric_part ? prm.symmetric_part_iterations : 0) +
             (single ? prm.single_precision_iterations : 0);
    }

    void
    LinearSolver::approximate_factors_failed(const unsigned int limit) const
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
      name(mumps != nullptr && mumps->factors_single(),
           "single-precision ",
           "Single-precision iterations, or Factor precision = double");
      name(mumps != nullptr && mumps->factors_symmetric_part(),
           "symmetric-part ",
           "Symmetric-part iterations, or Unsymmetric tangent = LU");
      AssertThrow(false,
                  ExcMessage("Linear solver: GMRES with the " + which +
                             "factors did not reach Reuse tolerance within " +
                             std::to_string(limit) + " iterations (raise " +
                             remedy + ")"));
      std::abort(); // not reached: AssertThrow(false, ...) throws
    }

    unsigned int
    LinearSolver::apply_current_factors(TrilinosWrappers::MPI::Vector       &x,
                                        const TrilinosWrappers::MPI::Vector &b)
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

    void LinearSolver::substitute(TrilinosWrappers::MPI::Vector       &x,
                                  const TrilinosWrappers::MPI::Vector &b)
    {
      const auto t = phase(timer, "linear solve: substitution");
      if (mumps)
        return mumps->solve(x, b);
      problem->SetLHS(&x.trilinos_vector());
      problem->SetRHS(const_cast<Epetra_MultiVector *>(&b.trilinos_vector()));
      AssertThrow(direct->Solve() == 0, ExcMessage("direct solve failed"));
    }

    void LinearSolver::substitute(TrilinosWrappers::MPI::Vector       &x,
                                  const TrilinosWrappers::MPI::Vector &b,
                                  TrilinosWrappers::MPI::Vector       &y,
                                  const TrilinosWrappers::MPI::Vector &c)
    {
      Assert(mumps != nullptr, ExcInternalError());
      const auto t = phase(timer, "linear solve: substitution");
      mumps->solve(x, b, y, c);
    }

    bool
    LinearSolver::gmres_with_factors(const TrilinosWrappers::SparseMatrix &A,
                                     TrilinosWrappers::MPI::Vector        &x,
                                     const TrilinosWrappers::MPI::Vector  &b,
                                     const unsigned int max_iterations,
                                     unsigned int      &iterations)
    {
      // The factors live in the solver (MUMPS, KLU), not in A: they stay
      // those of the matrix values at the last factorisation. Flexible
      // GMRES: x is built from the preconditioned vectors themselves, so the
      // residual tested is that of x (solver/flexible_gmres.h).
      const auto result = flexible_gmres(
        [&A](TrilinosWrappers::MPI::Vector       &dst,
             const TrilinosWrappers::MPI::Vector &src) { A.vmult(dst, src); },
        [this](TrilinosWrappers::MPI::Vector       &dst,
               const TrilinosWrappers::MPI::Vector &src) {
          substitute(dst, src);
        },
        x,
        b,
        std::max(prm.reuse_tolerance, forcing) * b.l2_norm(),
        max_iterations);
      iterations = result.iterations;
      return result.converged;
    }

    unsigned int
    LinearSolver::solve_again(TrilinosWrappers::MPI::Vector       &x,
                              const TrilinosWrappers::MPI::Vector &b)
    {
      Assert(last_matrix != nullptr, ExcInternalError());
      if (last_direct)
        {
          if (factors_current)
            return apply_current_factors(x, b);
          // The matrix of the last solve was not factorised: the same GMRES,
          // else its own factorisation.
          unsigned int its = 0;
          if (gmres_with_factors(*last_matrix, x, b, prm.reuse_iterations, its))
            return its;
          x = 0;
          return prm.reuse_iterations + factorise_and_substitute(x, b);
        }
      return iterate_or_fall_back(*last_matrix, x, b);
    }

    unsigned int LinearSolver::iterate(const TrilinosWrappers::SparseMatrix &A,
                                       TrilinosWrappers::MPI::Vector        &x,
                                       const TrilinosWrappers::MPI::Vector  &b)
    {
      SolverControl control(prm.max_iterations, prm.tolerance * b.l2_norm());
      if (prm.iterative_solver == parameters::IterativeSolver::cg)
        {
          SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
          cg.solve(A, x, b, *amg);
        }
      else
        {
          SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
            control,
            SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
              100,
              true)); // right preconditioning: the true residual
          gmres.solve(A, x, b, *amg);
        }
      return control.last_step();
    }
  } // namespace solver
} // namespace formsolve
