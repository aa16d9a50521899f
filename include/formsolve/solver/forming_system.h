// The discrete problem of one step, as Newton sees it: at every iterate the
// contact search, the penalty strategy, the body and contact assembly, and
// the linear solve (bordered with the blank-holder equation under force
// control). Data flows one way: search -> strategy -> assembly -> solve.
#pragma once

#include <deal.II/base/timer.h>

#include <formsolve/contact/contact_search.h>
#include <formsolve/contact/penalty_strategy.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/cell_scatter.h>
#include <formsolve/solver/factor_reuse.h>
#include <formsolve/solver/holder_coupling.h>
#include <formsolve/solver/linear_solver.h>
#include <formsolve/solver/newton_solver.h>
#include <formsolve/state/state.h>

#include <array>
#include <memory>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class FormingSystem : public NonlinearProblem
    {
    public:
      FormingSystem(const parameters::Run         &prm,
                    state::State<dim>             &state,
                    const Assembler<dim>          &assembler,
                    contact::PenaltyStrategy<dim> &strategy,
                    dealii::TimerOutput           &timer);

      /// Matrices, vectors and linear solver for the state's current mesh.
      void reinit();
      /// A step of @p dt begins (statistics of the step are reset).
      void begin_step(const double dt);
      /// A Newton solve of the step begins, from the state's velocity and
      /// holder velocity: the state's velocity is the iterate.
      void begin_solve();
      /// The solve has converged: the strategy sees the body system of the
      /// converged iterate (contact::PenaltyStrategy::converged).
      void end_solve();
      /// The step's predictor @p v (the previous step's velocity, holder at
      /// its last velocity), corrected at the contact nodes by Nonlinear
      /// solver/Predictor (contact::keep_contact). Call after begin_step().
      void predict(VectorType &v);

      /// Factors of the pairs of the last assembly (one per pair).
      const std::vector<double> &penalty_factors() const { return epsilon; }
      /// The holder's axial velocity of the accepted iterate (mm/s).
      double       holder_velocity() const { return w_accepted; }
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
      std::string info() const override { return iteration_info(); }

    private:
      /// Contact search, body and contact terms at @p v, with the tangent
      /// (counted); assemble_deferred(): the residual now, the tangent when
      /// it is needed (complete_tangent()).
      double assemble(const VectorType &v, const bool newton);
      double assemble_deferred(const VectorType &v, const bool newton);
      /// The tangent of eq. 4 (doc/theory.md) at @p v, the trials of the
      /// stress-velocity tangent forgotten (a rejected line search).
      double assemble_exact(const VectorType &v);
      /// K dv = -r with the last tangent (bordered by the holder's equation).
      unsigned int solve_direction(VectorType &dv);
      double       directional_derivative(const VectorType &dv) const;
      /// Whether the contact set changed since the last call.
      bool contact_set_changed();
      /// At an accepted iterate: new adaptive factors from its body system;
      /// -1 if nothing changed, else the new |r|.
      double update_penalty();
      /// The strict check near convergence: -1 or the new |r|.
      double      correct_penalty();
      std::string iteration_info() const;
      /// The holder's trial velocity at step length @p alpha.
      void set_step_length(const double alpha);
      void accept_step();
      /// The norms of the last evaluation with main residual @p r.
      Evaluation norms(const double r) const;
      double     extra_residual() const;
      double     extra_residual_norm() const;
      double     extra_correction() const;

      /// The contact search at velocity @p v with the holder at axial
      /// velocity @p w (under force control): the state's contact set.
      void find_pairs(const VectorType &v, const double w);
      /// Contact search, body and contact terms at @p v; the matrices only
      /// with @p with_matrix.
      double
      evaluate(const VectorType &v, const bool newton, const bool with_matrix);
      /// The deferred tangent of the last evaluation (assemble_deferred()),
      /// linearised about the iterate its trial was, if any: assembled now.
      void complete_tangent();
      /// Factors from the body system (r_b, K_b) of the current pairs.
      void estimate_penalty(const VectorType &r_b, const MatrixType &K_b);
      /// Contact forces and stiffness with the current factors added to the
      /// matrix and residual; holder coupling terms.
      void add_contact_terms(const bool with_matrix = true);
      /// The contact stiffness of the last assembly taken out of the matrix:
      /// the body tangent K_b, for the penalty estimate.
      void remove_contact_stiffness();
      /// contact::add_contact_terms() with the state's pairs, factors and
      /// tools, times @p sign, into what is given.
      void contact_terms(MatrixType  *into_matrix,
                         VectorType  *into_residual,
                         const double sign);
      /// For the iteration log: pairs closed and opened per tool since the
      /// last search (closed, opened; summed over ranks).
      void count_changes();
      bool holder_controlled() const { return state.holder.force_control; }

      /// The iterate (the state's velocity), its last direction and trial.
      VectorType *iterate = nullptr;
      VectorType  direction, trial;
      Evaluation  last_evaluation;

      const parameters::Run         &prm;
      state::State<dim>             &state;
      const Assembler<dim>          &assembler;
      contact::PenaltyStrategy<dim> &strategy;
      dealii::TimerOutput           &timer;
      contact::ContactSearch<dim>    search;

      MatrixType       matrix;
      CellScatter<dim> scatter; // positions of the cell tangents in matrix
      /// The body residual (no contact) of the last assembly, kept for
      /// penalty estimates at accepted iterates; the body tangent is the
      /// matrix after remove_contact_stiffness().
      VectorType residual, body_residual;
      /// The matrix holds the contact stiffness of the last assembly.
      bool contact_in_matrix = false;
      /// assemble_deferred(): the point whose tangent is still to come, its
      /// tangent type, and whether it has been accepted since.
      VectorType          deferred_point;
      bool                tangent_deferred = false, deferred_newton = true;
      bool                deferred_accepted = false;
      FactorReuse         factor_reuse;
      std::vector<double> epsilon;
      std::vector<bool>   last_active;
      /// Logging only: the status per contact record (node, tool) at the
      /// last search, and the pairs each tool closed/opened since then.
      std::vector<char>         last_record_status;
      std::vector<unsigned int> closed, opened;
      /// For the iteration log: quadrature points in the rigid zone at the
      /// accepted iterate, and those that became rigid and plastic since
      /// the previous iterate (summed over ranks).
      std::array<unsigned int, 3>   rigid_counts{{0, 0, 0}};
      std::unique_ptr<LinearSolver> linear_solver;
      DualStress                    dual;
      const bool                    use_dual;
      bool                          exact_tangent = false; // assemble_exact()
      bool hold_holder = false; // dw = 0 in the first correction of a step
      bool predictor_iterate = false; // the step's predictor not yet accepted
      HolderCoupling<dim> holder;
      double w_accepted = 0, w_trial = 0, dw = 0; // holder velocity (mm/s)

      double        dt              = 0;
      double        f_scale         = 0;
      bool          last_newton     = true; // tangent type of the last assembly
      unsigned int  step_max_linear = 0;
      double        step_condition  = 0;
      unsigned long n_matrix_assemblies = 0;
      unsigned long n_factorisations    = 0;
    };
  } // namespace solver
} // namespace formsolve
