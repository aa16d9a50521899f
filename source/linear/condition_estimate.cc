#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <formsolve/linear/condition_estimate.h>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    double estimate_condition(const TrilinosWrappers::SparseMatrix &A,
                              const TrilinosWrappers::MPI::Vector  &b,
                              const unsigned int                    iterations)
    {
      double condition = 0;
      // The Lanczos tridiagonal of CG gives the extreme eigenvalues; stop
      // after a fixed number of steps (convergence is not the point here).
      SolverControl control(iterations, 0., false, false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      cg.connect_condition_number_slot([&condition](
                                         const double c) { condition = c; },
                                       false);
      TrilinosWrappers::MPI::Vector y(b);
      y = 0;
      try
        {
          cg.solve(A, y, b, PreconditionIdentity());
        }
      catch (const SolverControl::NoConvergence &)
        {}
      return condition;
    }
  } // namespace solver
} // namespace formsolve
