#include <deal.II/base/exceptions.h>

#include <formsolve/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <iomanip>
#include <sstream>

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

    NewtonReport NewtonSolver::solve(NonlinearSystem             &system,
                                     NonlinearSystem::VectorType &v,
                                     const double check_residual) const
    {
      NewtonReport report;
      bool         picard   = prm.picard_iterations > 0;
      unsigned int fallback = 0; // direct iterations left after a stall
      double       r        = system.assemble(v, !picard);
      system.accept_step(); // v is the first linearisation point
      if (const double r_new = system.update_penalty(); r_new >= 0)
        r = r_new;
      system.contact_set_changed(); // reset: compare from here on
      // Merit of the line search: body and extra equations together.
      const auto merit = [&system](const double r_body) {
        return std::hypot(r_body, system.extra_residual_norm());
      };
      double m = merit(r);
      // Nonmonotone reference: the largest merit of the last
      // Line search memory iterates (doc/theory.md section 8).
      std::deque<double> merits{m};
      const auto         reference = [&merits]() {
        return *std::max_element(merits.begin(), merits.end());
      };
      log << "      it  0    |r|/|f|=" << std::scientific
          << std::setprecision(2) << r / std::max(system.force_scale(), 1e-300)
          << std::defaultfloat << system.iteration_info() << std::endl;
      NonlinearSystem::VectorType dv(v), trial(v);
      // The last correction, for the contraction estimate.
      bool   last_full = false, last_stalled = false;
      double last_step = 0, last_xstep = 0;
      // The error a correction (step, xstep) leaves (doc/theory.md section
      // 8): where it and the last one are full steps that contract by
      // theta <= 1/2, at most theta/(1 - theta) of it; else the correction
      // itself.
      const auto error_left =
        [&](const double step, const double xstep, const bool full) {
          if (prm.correction_measure ==
                parameters::CorrectionMeasure::contraction &&
              full && last_full && last_step > 0)
            {
              const double theta =
                std::max(step / last_step,
                         last_xstep > 0 ? xstep / last_xstep : 0.);
              if (theta <= 0.5)
                return theta / (1 - theta);
            }
          return 1.;
        };
      double r_prev = -1; // |r| of the iterate before v
      // Inexact Newton: once an inexact direction has failed in this solve,
      // the linear solves go to Reuse tolerance again.
      bool tight = prm.forcing == 0;

      for (unsigned int it = 1; it <= prm.max_iterations; ++it)
        {
          report.iterations = it;
          report.picard_iterations += picard;
          dv                      = 0;
          unsigned int linear_its = 0;
          if (prm.forcing > 0)
            {
              // Near the tolerance, no more accuracy than the next residual
              // needs: eta >= 0.5 tol/(|r|/|f|) (Kelley's safeguard,
              // doc/theory.md section 9).
              const double rel = r / std::max(system.force_scale(), 1e-300);
              system.set_linear_tolerance(
                tight ? 0.
                      : std::min(0.1,
                                 std::max(prm.forcing * rel,
                                          0.5 * prm.residual_tolerance /
                                            std::max(rel, 1e-300))));
            }
          try
            {
              linear_its = system.solve(dv);
              report.linear_iterations += linear_its;
            }
          catch (const dealii::ExceptionBase &e)
            {
              // The message of the exception, on one line.
              std::ostringstream info;
              e.print_info(info);
              std::istringstream words(info.str());
              std::string        message, word;
              while (words >> word)
                message += (message.empty() ? "" : " ") + word;
              report.failure = "linear solver failed (" + message + ")";
              return report;
            }
          catch (const std::exception &e)
            {
              report.failure =
                "linear solver failed (" + std::string(e.what()) + ")";
              return report;
            }
          if (!std::isfinite(dv.l2_norm()))
            {
              report.failure = "linear solver failed";
              return report;
            }

          // Line search on the directional derivative g(alpha) = dv . r(v +
          // alpha dv) of the (for frictionless contact convex) potential
          // (doc/theory.md section 8): accept a trial with a smaller merit
          // |(r, extra residual)| whose |g| has dropped to half. A trial that
          // still descends (g < 0, smaller merit) is too short: it becomes
          // the lower end of a bracket, which is then halved. Above any such
          // trial, regula falsi towards g = 0 where g turned positive, and
          // halving where g < 0 but the merit grew. When the trials run out,
          // the longest descending one is taken. The full step assembles the
          // matrix with the residual (it serves the next iteration when
          // accepted), or defers it where it is expected to be the last
          // iterate; shorter trials the residual only, and the accepted one
          // its matrix afterwards.
          const bool next_newton = fallback == 0 && it >= prm.picard_iterations;
          bool       stalled = false, with_matrix = true, deferred = false;
          const double g0    = system.directional_derivative(dv);
          double       alpha = 1, r_trial = 0, m_trial = 0;
          double       a_lo = 0, a_hi = 1, g_hi = 0;
          const double m_ref = reference();
          for (unsigned int ls = 0;; ++ls)
            {
              trial = v;
              trial.add(alpha, dv);
              system.set_step_length(alpha);
              with_matrix = ls == 0;
              if (ls == 0 && prm.deferred_tangent && next_newton && last_full &&
                  r_prev > 0)
                {
                  // Expected to be the last iterate: the quadratic model
                  // through the last two residuals, |r|^3/|r_prev|^2, passes
                  // the tolerance, and the correction meets its own. (The
                  // linear-rate model |r|^2/|r_prev| deferred half as often
                  // on the cups, doc/convergence.md.)
                  const double step  = dv.l2_norm();
                  const double xstep = system.extra_correction();
                  const double left  = error_left(step, xstep, true);
                  deferred =
                    r * (r / r_prev) * (r / r_prev) <=
                      prm.residual_tolerance * system.force_scale() &&
                    left * step <= prm.correction_tolerance * trial.l2_norm() &&
                    left * xstep <= prm.correction_tolerance;
                }
              r_trial        = !with_matrix ? system.assemble_residual(trial)
                               : deferred
                                 ? system.assemble_deferred(trial, next_newton)
                                 : system.assemble(trial, next_newton);
              m_trial        = merit(r_trial);
              const double g = system.directional_derivative(dv);
              const bool   descends = m_trial < m_ref && g < 0;
              if (!(g0 < 0) ||
                  (m_trial < m_ref && std::abs(g) <= 0.5 * std::abs(g0)) ||
                  (descends && alpha == 1))
                break;
              if (descends)
                a_lo = alpha;
              else
                {
                  a_hi = alpha;
                  g_hi = g;
                }
              if (ls >= prm.max_line_search_steps)
                {
                  stalled = a_lo == 0;
                  if (!stalled && alpha != a_lo)
                    {
                      alpha = a_lo;
                      trial = v;
                      trial.add(alpha, dv);
                      system.set_step_length(alpha);
                      with_matrix = false; // assembled below
                    }
                  break;
                }
              if (a_lo > 0)
                alpha = 0.5 * (a_lo + a_hi);
              else if (g_hi > 0 && std::abs(g_hi) > 0.5 * std::abs(g0))
                alpha =
                  std::clamp(a_hi * g0 / (g0 - g_hi), 0.1 * a_hi, 0.9 * a_hi);
              else
                alpha = 0.5 * a_hi;
            }
          if (!std::isfinite(r_trial))
            {
              report.failure = "Newton diverged";
              return report;
            }
          if (fallback > 0)
            --fallback;
          // An inexact direction that does not descend, or along which no
          // trial lowered the merit, is not taken: the iteration stays at v
          // and solves again to Reuse tolerance. Taking it (the full step
          // where g0 >= 0, a direct iteration after a stall) let a 262k-DoF
          // step diverge to |r|/|f| = 2e8 (doc/performance.md).
          const bool rejected = !tight && (stalled || !(g0 < 0));
          tight               = tight || rejected;
          // No trial lowered the merit: the direction does not descend |r|
          // (the stress-velocity tangent is not the derivative of r). Stay at
          // v and take the next direction from the exact tangent, whose
          // direction does, where r is smooth. If that stalls too: a few
          // direct (secant) iterations from the shortest trial, then Newton
          // again.
          const bool retry = !rejected && stalled && !last_stalled;
          last_stalled     = stalled && !rejected;
          if (rejected)
            {
              alpha = 0;
              trial = v;
              system.set_step_length(0);
              r_trial = system.assemble(trial, next_newton);
            }
          else if (retry)
            {
              alpha = 0;
              trial = v;
              system.set_step_length(0);
              r_trial = system.assemble_exact(trial);
            }
          else if (stalled && next_newton && prm.picard_fallback)
            {
              fallback = 3;
              r_trial  = system.assemble(trial, false);
            }
          else if (!with_matrix)
            r_trial = system.assemble(trial, next_newton);
          picard = !next_newton || fallback > 0;
          v      = trial;
          system.accept_step();
          if (const double r_new = system.update_penalty(); r_new >= 0)
            r_trial = r_new;
          const bool   changed = system.contact_set_changed();
          const double scale   = system.force_scale();
          const double step    = alpha * dv.l2_norm();
          const double xstep   = alpha * system.extra_correction();
          const double dv_rel  = step / std::max(v.l2_norm(), 1e-300);
          const bool   full    = alpha == 1 && !changed;
          const double left    = error_left(step, xstep, full);
          last_full            = full;
          last_step            = step;
          last_xstep           = xstep;
          r_prev               = r;
          r                    = r_trial;
          m                    = merit(r);
          merits.push_back(m);
          if (merits.size() > prm.line_search_memory)
            merits.pop_front();
          report.residual = r / std::max(scale, 1e-300);
          log << "      it " << std::setw(2) << it << (picard ? " P" : " N")
              << "  |r|/|f|=" << std::scientific << std::setprecision(2)
              << report.residual << "  |dv|/|v|=" << dv_rel
              << "  alpha=" << alpha << "  linear=" << linear_its
              << (changed ? "  contact set changed" : "")
              << (retry ? "  stalled: exact tangent" : "")
              << (rejected ? "  inexact direction rejected" : "")
              << (deferred && alpha == 1 ? "  tangent deferred" : "")
              << std::defaultfloat << system.iteration_info() << std::endl;
          // Near convergence, with the contact set settled: the strategy's
          // bound is checked here once; a correction changes the equations,
          // so the iteration goes on (doc/convergence.md).
          if (check_residual > 0 && !report.corrected && !changed &&
              report.residual <= check_residual)
            if (const double r_new = system.correct_penalty(); r_new >= 0)
              {
                report.corrected = true;
                r                = r_new;
                m                = merit(r);
                merits.assign(1, m); // new equations: a new reference
                report.residual = r / std::max(scale, 1e-300);
                last_full       = false;
                log << "      strict check: factors corrected, |r|/|f|="
                    << std::scientific << std::setprecision(2)
                    << report.residual << std::defaultfloat << std::endl;
                continue;
              }
          if (!retry && !rejected &&
              report.residual <= prm.residual_tolerance &&
              left * dv_rel <= prm.correction_tolerance && !changed &&
              system.extra_residual() <= prm.residual_tolerance &&
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
