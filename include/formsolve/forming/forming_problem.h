// The discrete problem of one step, as Newton sees it (a NonlinearProblem):
// the sheet's body operator, the contact operator and the force equations of
// the tools under force control, which border the system with each such
// tool's velocity as one more unknown. At every evaluation data flows one
// way: contact search -> body residual (and tangent) -> penalty factors ->
// contact and draw-bead terms -> force equations; the linear solve takes
// the result.
#pragma once

#include <deal.II/base/timer.h>

#include <formsolve/beads/bead_operator.h>
#include <formsolve/contact/penalty_strategy.h>
#include <formsolve/forming/assembler.h>
#include <formsolve/forming/body_operator.h>
#include <formsolve/forming/contact_operator.h>
#include <formsolve/forming/force_equations.h>
#include <formsolve/forming/iterate.h>
#include <formsolve/linear/factor_reuse.h>
#include <formsolve/linear/linear_solver.h>
#include <formsolve/newton/nonlinear_problem.h>
#include <formsolve/state/state.h>

#include <memory>
#include <string>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class FormingProblem : public NonlinearProblem
    {
    public:
      FormingProblem(const parameters::Run         &prm,
                     state::State<dim>             &state,
                     const Assembler<dim>          &assembler,
                     contact::PenaltyStrategy<dim> &strategy,
                     dealii::TimerOutput           &timer);

      /// Matrices, vectors and linear solver for the state's current mesh.
      void reinit();
      /// A step of @p dt begins (statistics of the step are reset).
      void begin_step(const double dt);
      /// A Newton solve of the step begins, from the state's velocity and
      /// force-controlled tools' velocities; the accepted iterate's velocity
      /// is written into the state's.
      void begin_solve();
      /// The solve has converged: the strategy sees the body system of the
      /// converged iterate (contact::PenaltyStrategy::converged), and the
      /// state's draw-bead records take its rates.
      void end_solve();
      /// The step's predictor @p v (the previous step's velocity, tools under
      /// force control at their last velocities), corrected at the contact
      /// nodes by Nonlinear solver/Predictor (contact::keep_contact). Call
      /// after begin_step().
      void predict(VectorType &v);

      /// One factor per pair of the state's contact set, the accepted
      /// iterate's (N/mm): 0 where the pairs have none yet.
      std::vector<double> penalty_factors() const
      {
        return contact.accepted_factors();
      }
      /// The body's internal forces int B^T sigma dV of the point evaluated
      /// last (at the end of a converged step: the converged iterate's,
      /// which the tools balance); condensed by the state's constraints.
      const VectorType &body_forces() const { return body_residual; }
      /// The point frames of the step's configuration (BodyOperator), if
      /// computed.
      const material::PointFrames<dim> *point_frames() const
      {
        return body.point_frames();
      }
      /// Velocity of force control j along its direction at the accepted
      /// iterate (mm/s).
      double control_velocity(const unsigned int j) const
      {
        return forces.velocity(j);
      }
      unsigned int max_linear_iterations() const { return step_max_linear; }
      double       condition_estimate() const { return step_condition; }
      /// Matrix assemblies since the start (line-search trials assemble the
      /// residual only).
      unsigned long matrix_assemblies() const { return n_matrix_assemblies; }
      /// Numeric factorisations of the direct solver since the start.
      unsigned long factorisations() const { return n_factorisations; }
      /// Frees the linear solver's factors (LinearSolver::release_factors).
      void release_factors()
      {
        if (linear_solver)
          linear_solver->release_factors();
      }
      /// Memory of the last MUMPS factorisation, all ranks (MB; 0 if none).
      double factorisation_memory_mb() const
      {
        return linear_solver ? linear_solver->factorisation_memory_mb() : 0.;
      }
      /// Entries of the last MUMPS factors (0 if none).
      double factor_entries() const
      {
        return linear_solver ? linear_solver->factor_entries() : 0.;
      }

      // NonlinearProblem
      Evaluation  evaluate(const double        alpha,
                           const Linearisation kind,
                           const bool          tangent_now) override;
      Direction   solve(const double tolerance) override;
      Accepted    accept() override;
      bool        tighten(Evaluation &evaluation) override;
      std::string info() const override;

    private:
      /// Search, body residual (and tangent), factors, contact forces and
      /// force equations at the point; returns |r|.
      double assemble(const bool with_tangent);
      /// The body residual r_b (and tangent K_b) of the point.
      void evaluate_body(const bool with_tangent);
      /// r = r_b + contact forces with the pairs' factors, and the force
      /// equations.
      void add_contact_forces();
      /// The draw beads' terms at the point into @p K and/or @p r.
      void add_beads(MatrixType *K, VectorType *r);
      /// The point's tangent, if it was left for later.
      void complete_tangent();
      /// The point's body system (r_b, K_b), its tangent assembled when a
      /// strategy first reads it.
      contact::SystemView body_system();
      /// At an accepted iterate: the strategy's factors from its body
      /// system; -1 if nothing changed, else the new |r|.
      double update_penalty();
      /// K dv = -r with the tangent of the iterate (bordered by the force
      /// equations).
      unsigned int solve_direction(VectorType &dv);
      double       directional_derivative(const VectorType &dv) const;
      Evaluation   norms(const double r) const;
      /// The largest last correction of a force-controlled tool relative to
      /// its velocity (-).
      double extra_correction() const;
      bool   newton(const Linearisation kind) const
      {
        return kind != Linearisation::secant;
      }
      /// A tool is under force control in this step.
      bool controlled() const { return forces.any_active(); }
      /// Whether the point is still the step's predictor (no iterate of the
      /// step accepted before it).
      bool predictor() const { return iterates == 0; }

      const parameters::Run   &prm;
      state::State<dim>       &state;
      dealii::TimerOutput     &timer;
      BodyOperator<dim>        body;
      ContactOperator<dim>     contact;
      beads::BeadOperator<dim> beads;
      ForceEquations<dim>      forces;

      /// The tangent of at most the point (Iterate::matrix says what).
      MatrixType matrix;
      /// The residual of the point and its body part r_b (no contact).
      VectorType                    residual, body_residual;
      std::unique_ptr<LinearSolver> linear_solver;
      FactorReuse                   factor_reuse;

      /// The point evaluated last; once accepted, its velocity is also the
      /// state's.
      Iterate    point;
      VectorType direction, ghost; // ghost: the point, with ghost values
      Evaluation last_evaluation;

      double        dt = 0, f_scale = 0;
      unsigned int  iterates            = 0; // accepted in the step
      unsigned int  corrections         = 0; // linear solves of the step
      unsigned int  step_max_linear     = 0;
      double        step_condition      = 0;
      unsigned long n_matrix_assemblies = 0;
      unsigned long n_factorisations    = 0;
    };
  } // namespace solver
} // namespace formsolve
