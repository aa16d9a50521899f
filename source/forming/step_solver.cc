#include <formsolve/forming/step_solver.h>
#include <formsolve/model/dimensions.h>

#include <iomanip>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    StepSolver<dim>::StepSolver(const parameters::Run    &prm,
                                state::State<dim>        &state,
                                const Assembler<dim>     &assembler,
                                TimerOutput              &timer,
                                const ConditionalOStream &log)
        : prm(prm)
        , state(state)
        , strategy(contact::create_penalty_strategy<dim>(prm.contact))
        , system(prm, state, assembler, *strategy, timer)
        , newton(prm.nonlinear,
                 ConditionalOStream(std::cout,
                                    log.is_active() &&
                                      prm.nonlinear.log_iterations))
        , control(prm.time)
        , log(log)
    {}

    template <int dim>
    StepReport StepSolver<dim>::solve(const double max_dt, const bool trial)
    {
      StepReport          report;
      const unsigned long assemblies = system.matrix_assemblies();
      const unsigned long factorised = system.factorisations();
      control.begin_step();
      state.update_contact_areas();
      for (;;)
        {
          const double              dt = std::min(control.time_step(), max_dt);
          const state::StepSnapshot start = state.snapshot();
          state.tools.begin_step(dt);
          // Set forces that follow the punch travel take their value at
          // the step's end, as the other unknowns.
          const unsigned int punch = state.tools.punch_index();
          state.set_force_targets(state.tools.punch_travel() +
                                  dt * (state.tools[punch].velocity() *
                                        state.tools.motion(punch).direction));
          system.begin_step(dt);
          // The previous step's velocity is the predictor, corrected where
          // it lifts nodes in contact off their tools.
          state.constraints.distribute(state.velocity);
          system.predict(state.velocity);
          NewtonReport attempt;
          unsigned int passes = 0;
          for (;; ++passes)
            {
              system.begin_solve();
              const auto r = newton.solve(system,
                                          passes < prm.contact.max_strict_passes
                                            ? prm.contact.strict_check_residual
                                            : 0.);
              // A correction within the solve counts as a pass.
              passes += r.corrected;
              attempt.converged = r.converged;
              attempt.failure   = r.failure;
              attempt.residual  = r.residual;
              attempt.iterations += r.iterations;
              attempt.linear_iterations += r.linear_iterations;
              attempt.picard_iterations += r.picard_iterations;
              if (!r.converged)
                break;
              for (unsigned int j = 0; j < state.force_controls.size(); ++j)
                state.force_controls[j].velocity = system.control_velocity(j);
              system.end_solve();
              // adaptive-strict: solve again while a node is deeper than
              // delta; augmented-lagrangian: update the multipliers, likewise.
              // No update after the last allowed pass: nothing would use it in
              // this step, and the next step must not inherit it.
              if (passes >= prm.contact.max_strict_passes ||
                  !strategy->finish_solve(state.contact_set,
                                          state.tools,
                                          state.contact_state,
                                          state.comm))
                break;
            }
          report.matrix_assemblies = system.matrix_assemblies() - assemblies;
          report.factorisations    = system.factorisations() - factorised;
          report.factorisation_memory_mb = system.factorisation_memory_mb();
          report.factor_entries          = system.factor_entries();
          report.iterations += attempt.iterations;
          report.linear_iterations += attempt.linear_iterations;
          report.picard_iterations += attempt.picard_iterations;
          report.residual = attempt.residual;
          report.max_linear_iterations =
            std::max(report.max_linear_iterations,
                     system.max_linear_iterations());
          report.condition_estimate =
            std::max(report.condition_estimate, system.condition_estimate());
          if (attempt.converged)
            {
              report.converged = true;
              report.dt        = dt;
              report.passes    = passes;
              report.cutbacks  = control.cutbacks();
              if (!trial)
                control.accept(attempt.iterations);
              return report;
            }
          report.failure = attempt.failure + " after " +
                           std::to_string(attempt.iterations) + " iterations";
          state.restore(start);
          if (trial)
            return report;
          const bool retry = control.reject(dt);
          report.cutbacks  = control.cutbacks();
          if (!retry)
            return report;
          log << "      step " << state.step + 1 << ": " << report.failure
              << " (|r|/|f| = " << std::scientific << std::setprecision(2)
              << attempt.residual << std::defaultfloat << ") with dt = " << dt
              << " s; retrying with dt = " << control.time_step() << " s"
              << std::endl;
        }
    }

    template <int dim>
    contact::ContactStatistics<dim>
    StepSolver<dim>::statistics(const double dt) const
    {
      return contact::statistics(state.tools,
                                 state.contact_set,
                                 system.penalty_factors(),
                                 prm.contact.regularisation_velocity,
                                 dt,
                                 state.comm);
    }

#define INSTANTIATE(dim) template class StepSolver<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
