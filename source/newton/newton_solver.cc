#include <deal.II/base/exceptions.h>

#include <formsolve/newton/line_search.h>
#include <formsolve/newton/newton_solver.h>
#include <formsolve/newton/newton_steps.h>

#include <cmath>
#include <iomanip>
#include <optional>
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

      /// One trial step: where the line search ended and how.
      struct Step
      {
        double        alpha = 1;
        Evaluation    trial;
        StallResponse stall;
        bool          deferred = false; // the full step's tangent deferred
      };

      /// One solve: the pieces and what they carry from iteration to
      /// iteration.
      class Solve
      {
      public:
        Solve(const parameters::NonlinearSolver &prm,
              NonlinearProblem                  &problem,
              ConditionalOStream                &log)
            : prm(prm)
            , problem(problem)
            , log(log)
            , picard(prm)
            , line_search(prm.max_line_search_steps)
            , error(prm.correction_measure)
            , stall(prm.forcing > 0, prm.picard_fallback)
        {}

        NewtonReport run(const double check_residual);

      private:
        /// The direction of iteration @p it, or a failure in the report.
        bool direction(Direction &d);
        /// The line search along @p d and what follows a stall.
        Step step(const Direction &d, const bool newton);
        /// Whether the full step's tangent may wait (doc/theory.md eq. 10c).
        bool defer(const Direction &d, const bool newton) const;
        void log_iteration(const unsigned int it,
                           const Step        &s,
                           const Direction   &d,
                           const bool         changed,
                           const double       dv_rel) const;

        const parameters::NonlinearSolver &prm;
        NonlinearProblem                  &problem;
        ConditionalOStream                &log;
        PicardSchedule                     picard;
        const LineSearch                   line_search;
        ErrorEstimate                      error;
        StallPolicy                        stall;
        NewtonReport                       report;
        std::optional<MeritHistory>        merits;
        Evaluation                         r;           // of the iterate
        double                             r_prev = -1; // |r| of the one before
      };

      bool Solve::direction(Direction &d)
      {
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
            return false;
          }
        if (!std::isfinite(d.norm))
          {
            report.failure = "linear solver failed";
            return false;
          }
        return true;
      }

      bool Solve::defer(const Direction &d, const bool newton) const
      {
        if (!prm.deferred_tangent || !newton || !error.full() || r_prev <= 0)
          return false;
        // Expected to be the last iterate: the quadratic model through the
        // last two residuals, |r|^3/|r_prev|^2, passes the tolerance, and the
        // correction meets its own. (The linear-rate model |r|^2/|r_prev|
        // deferred half as often on the cups, doc/convergence.md.)
        const double left = error.factor(d.norm, d.extra_relative, true);
        const double q    = r.residual / r_prev;
        return r.residual * q * q <= prm.residual_tolerance * r.scale &&
               left * d.norm <= prm.correction_tolerance * d.full_step_norm &&
               left * d.extra_relative <= prm.correction_tolerance;
      }

      Step Solve::step(const Direction &d, const bool newton)
      {
        // The full step assembles its tangent with its residual (it serves
        // the next iteration if accepted), or defers it where it is expected
        // to be the last iterate; shorter trials assemble their residual
        // only, and the accepted one its tangent after.
        Step       s;
        bool       with_tangent = true;
        const auto trial = [&](const double alpha, const unsigned int k) {
          with_tangent = k == 0;
          s.deferred   = k == 0 && defer(d, newton);
          s.trial      = problem.evaluate(alpha,
                                     linearisation(newton),
                                     with_tangent && !s.deferred);
          return LineSearchTrial{s.trial.merit(), s.trial.slope};
        };
        const LineSearchResult l =
          line_search.search(d.slope, merits->reference(), trial);
        s.alpha = l.alpha;
        if (!std::isfinite(s.trial.residual))
          return s;
        s.stall = stall.respond(l.stalled, d.slope < 0, newton);
        if (s.stall.rejected || s.stall.retry)
          {
            s.alpha = 0;
            s.trial = problem.evaluate(0,
                                       s.stall.retry ? Linearisation::exact
                                                     : linearisation(newton),
                                       true);
          }
        else if (s.stall.fallback)
          s.trial = problem.evaluate(s.alpha, Linearisation::secant, true);
        else if (!(with_tangent && l.evaluated))
          s.trial = problem.evaluate(s.alpha, linearisation(newton), true);
        return s;
      }

      void Solve::log_iteration(const unsigned int it,
                                const Step        &s,
                                const Direction   &d,
                                const bool         changed,
                                const double       dv_rel) const
      {
        log << "      it " << std::setw(2) << it
            << (picard.picard() ? " P" : " N")
            << "  |r|/|f|=" << std::scientific << std::setprecision(2)
            << report.residual << "  |dv|/|v|=" << dv_rel
            << "  alpha=" << s.alpha << "  linear=" << d.linear_iterations
            << (changed ? "  contact set changed" : "")
            << (s.stall.retry ? "  stalled: exact tangent" : "")
            << (s.stall.rejected ? "  inexact direction rejected" : "")
            << (s.deferred && s.alpha == 1 ? "  tangent deferred" : "")
            << std::defaultfloat << problem.info() << std::endl;
      }

      NewtonReport Solve::run(const double check_residual)
      {
        problem.evaluate(0, linearisation(!picard.picard()), true);
        r = problem.accept().evaluation; // the first linearisation point
        merits.emplace(prm.line_search_memory, r.merit());
        log << "      it  0    |r|/|f|=" << std::scientific
            << std::setprecision(2) << r.relative() << std::defaultfloat
            << problem.info() << std::endl;
        for (unsigned int it = 1; it <= prm.max_iterations; ++it)
          {
            report.iterations = it;
            report.picard_iterations += picard.picard();
            Direction d;
            if (!direction(d))
              return report;
            const bool newton = picard.newton_next(it);
            const Step s      = step(d, newton);
            if (!std::isfinite(s.trial.residual))
              {
                report.failure = "Newton diverged";
                return report;
              }
            picard.advance(it, s.stall.fallback);

            const Accepted a       = problem.accept();
            const bool     changed = a.active_set_changed;
            const double   step    = s.alpha * d.norm;
            const double   xstep   = s.alpha * a.extra_relative;
            const double   dv_rel  = step / std::max(a.norm, 1e-300);
            const bool     full    = s.alpha == 1 && !changed;
            const double   left    = error.factor(step, xstep, full);
            error.record(step, xstep, full);
            r_prev = r.residual;
            r      = a.evaluation;
            merits->push(r.merit());
            report.residual = r.relative();
            log_iteration(it, s, d, changed, dv_rel);
            // Near convergence, with the active set settled: the problem's
            // bound is checked here once; a change of the equations means
            // the iteration goes on (doc/convergence.md).
            if (check_residual > 0 && !report.corrected && !changed &&
                report.residual <= check_residual && problem.tighten(r))
              {
                report.corrected = true;
                merits->reset(r.merit()); // new equations: a new reference
                report.residual = r.relative();
                error.forget();
                log << "      strict check: factors corrected, |r|/|f|="
                    << std::scientific << std::setprecision(2)
                    << report.residual << std::defaultfloat << std::endl;
                continue;
              }
            if (!s.stall.retry && !s.stall.rejected &&
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
    } // namespace

    NewtonSolver::NewtonSolver(const parameters::NonlinearSolver &p,
                               ConditionalOStream                 log)
        : prm(p)
        , log(log)
    {}

    NewtonReport NewtonSolver::solve(NonlinearProblem &problem,
                                     const double      check_residual) const
    {
      return Solve(prm, problem, log).run(check_residual);
    }
  } // namespace solver
} // namespace formsolve
