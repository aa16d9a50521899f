#include <deal.II/base/exceptions.h>

#include <formsolve/solver/newton_solver.h>

#include <cmath>
#include <iomanip>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    NewtonSolver::NewtonSolver(const parameters::NonlinearSolver &p,
                               ConditionalOStream                 log)
      : prm(p)
      , log(log)
    {}

    NewtonReport NewtonSolver::solve(NonlinearSystem &            system,
                                     NonlinearSystem::VectorType &v) const
    {
      NewtonReport report;
      bool         picard   = prm.picard_iterations > 0;
      bool         fallback = false;
      double       r        = system.assemble(v, !picard);
      system.contact_set_changed(); // reset: compare from here on
      NonlinearSystem::VectorType dv(v), trial(v);

      for (unsigned int it = 1; it <= prm.max_iterations; ++it)
        {
          report.iterations = it;
          report.picard_iterations += picard;
          dv = 0;
          try
            {
              report.linear_iterations += system.solve(dv);
            }
          catch (const std::exception &e)
            {
              report.failure = "linear solver failed";
              return report;
            }
          if (!std::isfinite(dv.l2_norm()))
            {
              report.failure = "linear solver failed";
              return report;
            }

          // Backtracking on |r|; the last trial's assembly serves the next
          // iteration, so an accepted full step costs one assembly.
          const bool next_newton =
            !fallback && it >= prm.picard_iterations;
          double alpha = 1, r_trial = 0;
          for (unsigned int ls = 0;; ++ls)
            {
              trial = v;
              trial.add(alpha, dv);
              r_trial = system.assemble(trial, next_newton);
              if (r_trial < (1. - 1e-4 * alpha) * r || ls >= prm.max_line_search_steps)
                break;
              alpha *= 0.5;
            }
          if (!std::isfinite(r_trial))
            {
              report.failure = "Newton diverged";
              return report;
            }
          if (r_trial >= r && next_newton && prm.picard_fallback)
            {
              // Newton stalls: continue with direct iteration in this step.
              fallback = true;
              r_trial  = system.assemble(trial, false);
            }
          picard = !next_newton || fallback;
          v      = trial;
          const bool changed = system.contact_set_changed();
          const double scale = system.force_scale();
          const double dv_rel = alpha * dv.l2_norm() / std::max(v.l2_norm(), 1e-300);
          r = r_trial;
          report.residual = r / std::max(scale, 1e-300);
          log << "      it " << std::setw(2) << it << (picard ? " P" : " N")
              << "  |r|/|f|=" << std::scientific << std::setprecision(2)
              << report.residual << "  |dv|/|v|=" << dv_rel << "  alpha=" << alpha
              << (changed ? "  contact set changed" : "") << std::defaultfloat
              << std::endl;
          if (report.residual <= prm.residual_tolerance &&
              dv_rel <= prm.correction_tolerance && !changed)
            {
              report.converged = true;
              return report;
            }
        }
      report.failure = "Newton did not converge";
      return report;
    }
  } // namespace solver
} // namespace formsolve
