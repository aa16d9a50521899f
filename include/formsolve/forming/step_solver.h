// Solves one step of the process: Newton on the forming system, the strict
// or Uzawa re-solves the penalty strategy asks for, and step control (a
// failed try is undone and retried with a smaller time step).
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <formsolve/contact/contact_statistics.h>
#include <formsolve/contact/penalty_strategy.h>
#include <formsolve/forming/forming_problem.h>
#include <formsolve/newton/newton_solver.h>
#include <formsolve/newton/step_control.h>
#include <formsolve/state/state.h>

#include <memory>
#include <string>

namespace formsolve
{
  namespace solver
  {
    /// What a step cost and how it ended.
    struct StepReport
    {
      bool         converged         = false;
      double       dt                = 0; // time step of the converged try
      unsigned int cutbacks          = 0; // failed tries before it
      unsigned int iterations        = 0; // Newton iterations, all tries
      unsigned int linear_iterations = 0;
      unsigned int picard_iterations = 0;
      unsigned int passes            = 0;       // strict / Uzawa re-solves
      unsigned int matrix_assemblies = 0;       // tangent assemblies, all tries
      unsigned int factorisations    = 0;       // numeric, all tries
      double       factorisation_memory_mb = 0; // MUMPS, all ranks
      double       factor_entries          = 0; // MUMPS
      unsigned int max_linear_iterations   = 0;
      double       condition_estimate      = 0;
      double       residual                = 0; // |r|/|f| of the last try
      std::string  failure;                     // why the last try failed
    };

    template <int dim>
    class StepSolver
    {
    public:
      StepSolver(const parameters::Run            &prm,
                 state::State<dim>                &state,
                 const Assembler<dim>             &assembler,
                 dealii::TimerOutput              &timer,
                 const dealii::ConditionalOStream &log);

      /// After the mesh changed.
      void reinit() { system.reinit(); }
      /// Between steps, before a phase that needs memory of its own.
      void release_factors() { system.release_factors(); }

      /// Solves the next step, at most @p max_dt long. On success the
      /// state's velocity, contact state and holder velocity are those of
      /// the converged step (the geometry is not advanced yet); on failure
      /// at the minimum time step they are those of the start of the step.
      /// With @p trial, one try at the current time step and no step
      /// control: the step control is left as it was, and a failed try is
      /// undone and returned (a start for the real solve, e.g. on a
      /// coarser mesh).
      StepReport solve(const double max_dt, const bool trial = false);

      /// Forces and penetrations of the last converged step.
      contact::ContactStatistics<dim> statistics(const double dt) const;

      const FormingProblem<dim> &forming_system() const { return system; }
      std::string strategy_name() const { return strategy->name(); }
      /// The time step the next step starts with (step control).
      double time_step() const { return control.time_step(); }
      void   set_time_step(const double t) { control.set_time_step(t); }

    private:
      const parameters::Run                         &prm;
      state::State<dim>                             &state;
      std::unique_ptr<contact::PenaltyStrategy<dim>> strategy;
      FormingProblem<dim>                            system;
      NewtonSolver                                   newton;
      StepControl                                    control;
      dealii::ConditionalOStream                     log;
    };
  } // namespace solver
} // namespace formsolve
