#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <formsolve/solver/linear_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

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
                                     const TrilinosWrappers::MPI::Vector  &b)
    {
      estimate_condition(A, b);
      last_matrix = &A;
      if (prm.type == parameters::LinearSolverType::direct)
        {
          auto &matrix = const_cast<Epetra_CrsMatrix &>(A.trilinos_matrix());
          const bool same_pattern = factorised_matrix == &matrix &&
                                    factorised_nnz == A.n_nonzero_elements();
          if (same_pattern && n_factorisations > 0 && prm.reuse_iterations > 0)
            {
              unsigned int its = 0;
              if (reuse(A, x, b, its))
                {
                  factors_current = false;
                  return its;
                }
              x = 0;
            }
          if (!same_pattern &&
              prm.direct_solver == parameters::DirectSolver::mumps)
            {
              MumpsDirect::Settings settings;
              settings.symmetric   = symmetric && prm.symmetric_factorisation;
              settings.metis_order = prm.metis_order;
              settings.refinement_steps = prm.refinement_steps;
              mumps.reset();
              const auto t = phase(timer, "linear solve: analysis");
              mumps = std::make_unique<MumpsDirect>(A.get_mpi_communicator(),
                                                    settings);
              mumps->analyse(A);
              factorised_matrix = &matrix;
              factorised_nnz    = A.n_nonzero_elements();
            }
          else if (!same_pattern)
            {
              const auto t = phase(timer, "linear solve: analysis");
              problem      = std::make_unique<Epetra_LinearProblem>();
              problem->SetOperator(&matrix);
              Amesos     factory;
              const bool amesos_mumps =
                prm.direct_solver == parameters::DirectSolver::amesos_mumps;
              direct.reset(
                factory.Create(amesos_mumps ? "Amesos_Mumps" : "Amesos_Klu",
                               *problem));
              AssertThrow(direct != nullptr,
                          ExcMessage(
                            "Linear solver/Direct solver: Amesos has no " +
                            std::string(amesos_mumps ? "MUMPS" : "KLU")));
              AssertThrow(direct->SymbolicFactorization() == 0,
                          ExcMessage("symbolic factorisation failed"));
              factorised_matrix = &matrix;
              factorised_nnz    = A.n_nonzero_elements();
            }
          return factorise_and_substitute(x, b);
        }

      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      data.constant_modes        = constant_modes;
      amg->initialize(A, data);
      return iterate(A, x, b);
    }

    unsigned int LinearSolver::factorise_and_substitute(
      TrilinosWrappers::MPI::Vector       &x,
      const TrilinosWrappers::MPI::Vector &b)
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
      substitute(x, b);
      return 1;
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

    bool LinearSolver::reuse(const TrilinosWrappers::SparseMatrix &A,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b,
                             unsigned int                         &iterations)
    {
      // The factors live in the solver (MUMPS, KLU), not in A: they stay
      // those of the matrix values at the last factorisation.
      struct Factors
      {
        LinearSolver *solver;
        void          vmult(TrilinosWrappers::MPI::Vector       &dst,
                            const TrilinosWrappers::MPI::Vector &src) const
        {
          solver->substitute(dst, src);
        }
      } factors{this};
      SolverControl                              control(prm.reuse_iterations,
                            prm.reuse_tolerance * b.l2_norm(),
                            false,
                            false);
      SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
        control,
        SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
          prm.reuse_iterations + 2,
          true)); // right preconditioning: the true residual is tested
      try
        {
          gmres.solve(A, x, b, factors);
        }
      catch (const SolverControl::NoConvergence &)
        {
          return false;
        }
      iterations = control.last_step();
      return true;
    }

    unsigned int
    LinearSolver::solve_again(TrilinosWrappers::MPI::Vector       &x,
                              const TrilinosWrappers::MPI::Vector &b)
    {
      Assert(last_matrix != nullptr, ExcInternalError());
      if (prm.type == parameters::LinearSolverType::direct)
        {
          if (factors_current)
            {
              substitute(x, b);
              return 1;
            }
          // The matrix of the last solve was not factorised: the same GMRES,
          // else its own factorisation.
          unsigned int its = 0;
          if (reuse(*last_matrix, x, b, its))
            return its;
          x = 0;
          return factorise_and_substitute(x, b);
        }
      return iterate(*last_matrix, x, b);
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
            SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(100));
          gmres.solve(A, x, b, *amg);
        }
      return control.last_step();
    }
  } // namespace solver
} // namespace formsolve
