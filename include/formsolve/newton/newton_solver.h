// Newton's method with a line search on a NonlinearProblem
// (doc/theory.md, sections 8 and 9). The pieces it is made of are in
// line_search.h and newton_steps.h.
#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <formsolve/newton/nonlinear_problem.h>
#include <formsolve/parameters/solvers.h>

#include <string>

namespace formsolve
{
  namespace solver
  {
    struct NewtonReport
    {
      bool         converged         = false;
      unsigned int iterations        = 0;
      unsigned int linear_iterations = 0;
      unsigned int picard_iterations = 0;
      double       residual          = 0;     // |r|/|f| of the last iterate
      bool         corrected         = false; // tighten() changed the equations
      std::string  failure;
    };

    class NewtonSolver
    {
    public:
      NewtonSolver(const parameters::NonlinearSolver &p,
                   dealii::ConditionalOStream         log);

      /// Iterates from the problem's current iterate until |r|/|f|, the
      /// error left in the unknowns and the extra residual meet their
      /// tolerances with the active set unchanged. Once |r|/|f| <=
      /// @p check_residual (> 0) with the active set unchanged, the problem
      /// may tighten its equations, once per solve.
      NewtonReport solve(NonlinearProblem &problem,
                         const double      check_residual = 0) const;

    private:
      parameters::NonlinearSolver        prm;
      mutable dealii::ConditionalOStream log;
    };
  } // namespace solver
} // namespace formsolve
