#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/contact/contact_predictor.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/solver/forming_system.h>
#include <formsolve/solver/null_space.h>

#include <cmath>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    FormingSystem<dim>::FormingSystem(const parameters::Run         &prm,
                                      state::State<dim>             &state,
                                      const Assembler<dim>          &assembler,
                                      contact::PenaltyStrategy<dim> &strategy,
                                      TimerOutput                   &timer)
        : prm(prm)
        , state(state)
        , assembler(assembler)
        , strategy(strategy)
        , timer(timer)
        , search(prm.contact.search_distance)
        , factor_reuse(prm.linear.reuse_velocity_change)
        , use_dual(prm.nonlinear.tangent ==
                   parameters::Tangent::stress_velocity)
    {}

    template <int dim>
    void FormingSystem<dim>::reinit()
    {
      // The direct solver refers to the matrix: release it first. The old
      // system goes before the new one is built, so that the two never
      // coexist (a remeshing, the coarse start).
      linear_solver.reset();
      matrix.clear();
      contact_in_matrix = false;
      tangent_deferred  = false;
      scatter           = CellScatter<dim>();
      dual              = DualStress();
      {
        DynamicSparsityPattern dsp(state.relevant);
        // ML's line detection needs every ghost node with all its
        // components in the column map ("Incomplete ghost block detected"
        // on 2 ranks otherwise): keep the (zero) couplings of constrained
        // DoFs.
        DoFTools::make_sparsity_pattern(
          state.dof_handler,
          dsp,
          state.constraints,
          prm.linear.type == parameters::LinearSolverType::iterative);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   state.owned,
                                                   state.comm,
                                                   state.relevant);
        matrix.reinit(state.owned, state.owned, dsp, state.comm);
      } // the pattern (0.4 kB/DoF) is freed before the cell map is built
      scatter.reinit(state.dof_handler, state.constraints, matrix);
      residual.reinit(state.owned, state.comm);
      body_residual.reinit(state.owned, state.comm);
      direction.reinit(state.owned, state.comm);
      trial.reinit(state.owned, state.comm);
      factor_reuse.reinit(state.owned, state.comm);
      holder.reinit(state.owned, state.comm);
      epsilon.clear();
      last_active.clear();
      last_record_status.clear(); // new surface nodes
      dual.reinit(state.dof_handler.get_triangulation().n_active_cells(),
                  assembler.quadrature().size());

      std::vector<std::vector<bool>> modes;
      DoFTools::extract_constant_modes(state.dof_handler,
                                       ComponentMask(dim, true),
                                       modes);
      linear_solver = std::make_unique<LinearSolver>(prm.linear,
                                                     modes,
                                                     prm.symmetric_tangent());
      linear_solver->time_phases(timer);
    }

    template <int dim>
    void FormingSystem<dim>::begin_step(const double step_dt)
    {
      dt = step_dt;
      // Each step starts from the secant tangent: the last step's
      // linearisation point lies in another configuration (and a resumed run
      // must iterate as the uninterrupted one).
      dual.reset();
      tangent_deferred  = false;
      predictor_iterate = true;
      hold_holder       = true;
      step_max_linear   = 0;
      step_condition    = 0;
    }

    template <int dim>
    void FormingSystem<dim>::begin_solve()
    {
      state.contact_state.begin_solve();
      strategy.begin_solve();
      factor_reuse.begin_solve();
      w_accepted = w_trial = state.holder.velocity;
      dw                   = 0;
      iterate              = &state.velocity;
      direction            = 0;
    }

    template <int dim>
    void FormingSystem<dim>::find_pairs(const VectorType &v, const double w)
    {
      state.velocity_ghost = v;
      if (holder_controlled())
        state.tools.set_axial_velocity(state.tools.holder_index(), w);
      search.evaluate(state.tools,
                      state.displacement_ghost,
                      state.velocity_ghost,
                      dt,
                      state.contact_state,
                      state.contact_set);
    }

    template <int dim>
    void FormingSystem<dim>::predict(VectorType &v)
    {
      if (prm.nonlinear.predictor != parameters::Predictor::keep_contact)
        return;
      TimerOutput::Scope t(timer, "contact");
      // No track_status(): the status of the previous solve is what
      // keep_contact() reads.
      find_pairs(v, state.holder.velocity);
      VectorType change(state.owned, state.comm);
      contact::keep_contact(state.contact_set,
                            state.contact_state,
                            state.tools,
                            dt,
                            change);
      change.compress(VectorOperation::add);
      v += change;
      state.constraints.distribute(v);
    }

    template <int dim>
    double FormingSystem<dim>::assemble(const VectorType &v, const bool newton)
    {
      ++n_matrix_assemblies;
      return evaluate(v, newton, true);
    }

    template <int dim>
    double FormingSystem<dim>::assemble_deferred(const VectorType &v,
                                                 const bool        newton)
    {
      const double r   = evaluate(v, newton, false);
      deferred_point   = v;
      deferred_newton  = newton;
      tangent_deferred = true;
      return r;
    }

    template <int dim>
    void FormingSystem<dim>::complete_tangent()
    {
      if (!tangent_deferred)
        return;
      // The stress-velocity tangent of the trial is linearised about the
      // iterate before it, as in an assembly before the acceptance.
      const bool accepted = deferred_accepted;
      if (accepted && use_dual)
        dual.revert();
      assemble(deferred_point, deferred_newton);
      if (accepted && use_dual)
        dual.accept();
    }

    template <int dim>
    double FormingSystem<dim>::assemble_exact(const VectorType &v)
    {
      dual.restart(assembler.cutoff_rate(), assembler.smooth_rigid_zone());
      exact_tangent  = true;
      const double r = assemble(v, true);
      exact_tangent  = false;
      return r;
    }

    template <int dim>
    double FormingSystem<dim>::evaluate(const VectorType &v,
                                        const bool        newton,
                                        const bool        with_matrix)
    {
      tangent_deferred  = false; // a new trial: a deferred one is dropped
      deferred_accepted = false;
      {
        TimerOutput::Scope t(timer, "contact");
        find_pairs(v, w_trial);
        state.contact_state.track_status(state.contact_set,
                                         prm.contact.max_status_flips);
      }
      // Body first: an adaptive strategy reads its residual and tangent;
      // then the factors, then the contact terms with them.
      {
        // Separate sections: the cost per cell of each kind is measured
        // (doc/convergence.md).
        TimerOutput::Scope t(timer,
                             with_matrix ? "assembly: body, tangent"
                                         : "assembly: body, residual only");
        f_scale =
          assembler.assemble_body(state.dof_handler,
                                  *state.mapping,
                                  state.constraints,
                                  state.velocity_ghost,
                                  state.history,
                                  dt,
                                  newton,
                                  with_matrix ? &matrix : nullptr,
                                  residual,
                                  use_dual && !exact_tangent ? &dual : nullptr,
                                  &scatter);
      }
      // Line-search trials (no matrix) keep the factors of the iterate.
      bool estimate = !strategy.needs_system();
      if (strategy.needs_system() && with_matrix)
        {
          // Keep the body residual for update_penalty() (the body tangent
          // comes back by remove_contact_stiffness()); estimate here only
          // when there are no factors for these pairs yet.
          body_residual = residual;
          // The estimate is collective: decide on all ranks alike.
          estimate = Utilities::MPI::max(int(epsilon.size() !=
                                             state.contact_set.pairs.size()),
                                         state.comm) != 0;
        }
      if (estimate)
        estimate_penalty(residual, matrix);
      last_newton = newton;
      if (with_matrix)
        factor_reuse.assembled_at(v);
      add_contact_terms(with_matrix);
      return residual.l2_norm();
    }

    template <int dim>
    Evaluation FormingSystem<dim>::evaluate(const double        alpha,
                                            const Linearisation kind,
                                            const bool          tangent_now)
    {
      trial = *iterate;
      trial.add(alpha, direction);
      set_step_length(alpha);
      const bool   newton = kind != Linearisation::secant;
      const double r      = kind == Linearisation::exact ? assemble_exact(trial)
                            : tangent_now ? assemble(trial, newton)
                                          : assemble_deferred(trial, newton);
      last_evaluation     = norms(r);
      last_evaluation.slope = directional_derivative(direction);
      return last_evaluation;
    }

    template <int dim>
    Direction FormingSystem<dim>::solve(const double tolerance)
    {
      linear_solver->set_forcing(tolerance);
      Direction d;
      direction           = 0;
      d.linear_iterations = solve_direction(direction);
      d.norm              = direction.l2_norm();
      trial               = *iterate;
      trial.add(1., direction);
      d.full_step_norm = trial.l2_norm();
      d.extra_relative = extra_correction();
      d.slope          = directional_derivative(direction);
      return d;
    }

    template <int dim>
    Accepted FormingSystem<dim>::accept()
    {
      *iterate = trial;
      accept_step();
      Accepted     a;
      const double r = update_penalty();
      a.evaluation   = r >= 0 ? norms(r) : norms(last_evaluation.residual);
      a.active_set_changed = contact_set_changed();
      a.norm               = iterate->l2_norm();
      a.extra_relative     = extra_correction();
      return a;
    }

    template <int dim>
    bool FormingSystem<dim>::tighten(Evaluation &evaluation)
    {
      const double r = correct_penalty();
      if (r < 0)
        return false;
      evaluation = norms(r);
      return true;
    }

    template <int dim>
    Evaluation FormingSystem<dim>::norms(const double r) const
    {
      Evaluation e;
      e.residual       = r;
      e.extra          = extra_residual_norm();
      e.extra_relative = extra_residual();
      e.scale          = f_scale;
      return e;
    }

    template <int dim>
    unsigned int FormingSystem<dim>::solve_direction(VectorType &dv)
    {
      complete_tangent();
      TimerOutput::Scope t(timer, "linear solve");
      VectorType         rhs(residual);
      rhs *= -1.;
      const unsigned long factorised = linear_solver->factorisations();
      if (linear_solver->needs_null_space())
        linear_solver->set_null_space(rigid_body_modes(
          state.mapping
            ? static_cast<const Mapping<dim> &>(*state.mapping)
            : static_cast<const Mapping<dim> &>(state.reference_mapping),
          state.dof_handler,
          state.owned));
      // Bordered system (the holder under force control): the holder's
      // column K z = b with the same factors, in the same solve.
      const bool bordered =
        holder_controlled() && holder.engaged() && !hold_holder;
      unsigned int its = 0;
      if (bordered)
        {
          VectorType z(state.owned, state.comm);
          its = linear_solver->solve_pair(matrix,
                                          dv,
                                          rhs,
                                          z,
                                          holder.column(),
                                          factor_reuse.may_reuse());
          dw  = holder.correction(dv, z);
          dv.add(-dw, z);
        }
      else
        {
          its = linear_solver->solve(matrix, dv, rhs, factor_reuse.may_reuse());
          // The first correction of a step comes from the secant tangent
          // (dual reset), under which the sheet below the holder is 5-10x
          // softer than in Newton's: the Schur complement (e - c^T K^-1 b)
          // is then 2e-4 e, and dw about 100x the holder's speed. The
          // holder keeps its velocity for that one correction (doc/theory.md
          // section 6a), and K^-1 b is not needed.
          dw = 0;
          if (holder_controlled() && !holder.engaged())
            dw = holder.closing_correction(state.tools.allowed_penetration(
                                             state.tools.holder_index()),
                                           dt);
        }
      hold_holder = false;
      if (linear_solver->factorisations() != factorised)
        factor_reuse.factorised();
      n_factorisations += linear_solver->factorisations() - factorised;
      step_max_linear = std::max(step_max_linear, its);
      step_condition =
        std::max(step_condition, linear_solver->condition_estimate());
      state.constraints.distribute(dv);
      return its;
    }

    template <int dim>
    double
    FormingSystem<dim>::directional_derivative(const VectorType &dv) const
    {
      return residual * dv +
             (holder_controlled() ? dw * holder.residual() : 0.);
    }

    template <int dim>
    void FormingSystem<dim>::accept_step()
    {
      deferred_accepted = tangent_deferred;
      w_accepted        = w_trial;
      if (!use_dual)
        return;
      if (prm.nonlinear.log_iterations)
        {
          // Rigid-plastic transitions: a category of hard steps
          // (doc/convergence.md).
          rigid_counts   = dual.rigid_transitions(assembler.cutoff_rate());
          const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                         rigid_counts.data(),
                                         3,
                                         MPI_UNSIGNED,
                                         MPI_SUM,
                                         state.comm);
          AssertThrowMPI(ierr);
        }
      dual.accept();
    }

    template <int dim>
    void FormingSystem<dim>::set_step_length(const double alpha)
    {
      w_trial = w_accepted + alpha * dw;
    }

    template <int dim>
    double FormingSystem<dim>::extra_residual() const
    {
      return holder_controlled()
               ? std::abs(holder.residual()) / state.holder.target
               : 0.;
    }

    template <int dim>
    double FormingSystem<dim>::extra_residual_norm() const
    {
      // rho is a force (N), as the nodal entries of r.
      return holder_controlled() ? std::abs(holder.residual()) : 0.;
    }

    template <int dim>
    double FormingSystem<dim>::extra_correction() const
    {
      return holder_controlled()
               ? std::abs(dw) /
                   std::max(std::abs(w_accepted), state.tools.punch_speed())
               : 0.;
    }

#define INSTANTIATE(dim) template class FormingSystem<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
