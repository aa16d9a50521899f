#include <deal.II/base/exceptions.h>

#include <formsolve/solver/line_search.h>
#include <formsolve/solver/newton_solver.h>
#include <formsolve/solver/newton_steps.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    namespace
    {
      /// The message of a failed linear solve, on one line.
      std::string linear_failure(const std::exception &e)
      {
        std::ostringstream info;
        if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
          d->print_info(info);
        else
          info << e.what();
        std::istringstream words(info.str());
        std::string        message, word;
        while (words >> word)
          message += (message.empty() ? "" : " ") + word;
        return "linear solver failed (" + message + ")";
      }

      Linearisation linearisation(const bool newton)
      {
        return newton ? Linearisation::newton : Linearisation::secant;
      }
    } // namespace

    NewtonSolver::NewtonSolver(const parameters::NonlinearSolver &p,
                               ConditionalOStream                 log)
        : prm(p)
        , log(log)
    {}

    NewtonReport NewtonSolver::solve(NonlinearProblem &problem,
                                     const double      check_residual) const
    {
      NewtonReport   report;
      PicardSchedule picard(prm);
      problem.evaluate(0, linearisation(!picard.picard()), true);
      Accepted     current = problem.accept(); // the first linearisation point
      Evaluation   r       = current.evaluation;
      MeritHistory merits(prm.line_search_memory, r.merit());
      log << "      it  0    |r|/|f|=" << std::scientific
          << std::setprecision(2) << r.relative() << std::defaultfloat
          << problem.info() << std::endl;
      const LineSearch line_search(prm.max_line_search_steps);
      ErrorEstimate    error(prm.correction_measure);
      StallPolicy      stall(prm.forcing > 0, prm.picard_fallback);
      double           r_prev = -1; // |r| of the iterate before

      for (unsigned int it = 1; it <= prm.max_iterations; ++it)
        {
          report.iterations = it;
          report.picard_iterations += picard.picard();
          Direction d;
          try
            {
              d = problem.solve(
                prm.forcing > 0
                  ? linear_tolerance(prm, r.relative(), stall.tight())
                  : 0.);
              report.linear_iterations += d.linear_iterations;
            }
          catch (const std::exception &e)
            {
              report.failure = linear_failure(e);
              return report;
            }
          if (!std::isfinite(d.norm))
            {
              report.failure = "linear solver failed";
              return report;
            }

          // The full step assembles its tangent with its residual (it
          // serves the next iteration if accepted), or defers it where it
          // is expected to be the last iterate; shorter trials assemble
          // their residual only, and the accepted one its tangent after.
          const bool newton   = picard.newton_next(it);
          bool       deferred = false, with_tangent = true;
          Evaluation trial;
          const auto evaluate = [&](const double alpha, const unsigned int k) {
            with_tangent = k == 0;
            if (k == 0 && prm.deferred_tangent && newton && error.full() &&
                r_prev > 0)
              {
                // Expected to be the last iterate: the quadratic model
                // through the last two residuals, |r|^3/|r_prev|^2, passes
                // the tolerance, and the correction meets its own. (The
                // linear-rate model |r|^2/|r_prev| deferred half as often
                // on the cups, doc/convergence.md.)
                const double left =
                  error.factor(d.norm, d.extra_relative, true);
                const double q = r.residual / r_prev;
                deferred =
                  r.residual * q * q <= prm.residual_tolerance * r.scale &&
                  left * d.norm <=
                    prm.correction_tolerance * d.full_step_norm &&
                  left * d.extra_relative <= prm.correction_tolerance;
              }
            trial = problem.evaluate(alpha,
                                     linearisation(newton),
                                     with_tangent && !deferred);
            return LineSearchTrial{trial.merit(), trial.slope};
          };
          const LineSearchResult s =
            line_search.search(d.slope, merits.reference(), evaluate);
          if (!std::isfinite(trial.residual))
            {
              report.failure = "Newton diverged";
              return report;
            }
          const StallResponse stalled =
            stall.respond(s.stalled, d.slope < 0, newton);
          double alpha = s.alpha;
          if (stalled.rejected || stalled.retry)
            {
              alpha = 0;
              trial = problem.evaluate(0,
                                       stalled.retry ? Linearisation::exact
                                                     : linearisation(newton),
                                       true);
            }
          else if (stalled.fallback)
            trial = problem.evaluate(alpha, Linearisation::secant, true);
          else if (!(with_tangent && s.evaluated))
            trial = problem.evaluate(alpha, linearisation(newton), true);
          picard.advance(it, stalled.fallback);

          current              = problem.accept();
          const bool   changed = current.active_set_changed;
          const double step    = alpha * d.norm;
          const double xstep   = alpha * current.extra_relative;
          const double dv_rel  = step / std::max(current.norm, 1e-300);
          const bool   full    = alpha == 1 && !changed;
          const double left    = error.factor(step, xstep, full);
          error.record(step, xstep, full);
          r_prev = r.residual;
          r      = current.evaluation;
          merits.push(r.merit());
          report.residual = r.relative();
          log << "      it " << std::setw(2) << it
              << (picard.picard() ? " P" : " N")
              << "  |r|/|f|=" << std::scientific << std::setprecision(2)
              << report.residual << "  |dv|/|v|=" << dv_rel
              << "  alpha=" << alpha << "  linear=" << d.linear_iterations
              << (changed ? "  contact set changed" : "")
              << (stalled.retry ? "  stalled: exact tangent" : "")
              << (stalled.rejected ? "  inexact direction rejected" : "")
              << (deferred && alpha == 1 ? "  tangent deferred" : "")
              << std::defaultfloat << problem.info() << std::endl;
          // Near convergence, with the active set settled: the problem's
          // bound is checked here once; a change of the equations means
          // the iteration goes on (doc/convergence.md).
          if (check_residual > 0 && !report.corrected && !changed &&
              report.residual <= check_residual && problem.tighten(r))
            {
              report.corrected = true;
              merits.reset(r.merit()); // new equations: a new reference
              report.residual = r.relative();
              error.forget();
              log << "      strict check: factors corrected, |r|/|f|="
                  << std::scientific << std::setprecision(2) << report.residual
                  << std::defaultfloat << std::endl;
              continue;
            }
          if (!stalled.retry && !stalled.rejected &&
              report.residual <= prm.residual_tolerance &&
              left * dv_rel <= prm.correction_tolerance && !changed &&
              r.extra_relative <= prm.residual_tolerance &&
              left * xstep <= prm.correction_tolerance)
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
