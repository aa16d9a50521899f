#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/forming/forming_problem.h>
#include <formsolve/linear/condition_estimate.h>
#include <formsolve/model/dimensions.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    FormingProblem<dim>::FormingProblem(const parameters::Run &prm,
                                        state::State<dim>     &state,
                                        const Assembler<dim>  &assembler,
                                        contact::PenaltyStrategy<dim> &strategy,
                                        TimerOutput                   &timer)
        : prm(prm)
        , state(state)
        , timer(timer)
        , body(assembler, prm.nonlinear)
        , contact(prm, state, strategy, timer)
        , factor_reuse(prm.linear.reuse_velocity_change)
    {}

    template <int dim>
    void FormingProblem<dim>::reinit()
    {
      // The direct solver refers to the matrix: release it first. The old
      // system goes before the new one is built, so that the two never
      // coexist (a remeshing, the coarse start).
      linear_solver.reset();
      matrix.clear();
      matrix_has_contact = false;
      point.tangent      = true;
      body.clear();
      {
        DynamicSparsityPattern dsp(state.relevant);
        DoFTools::make_sparsity_pattern(state.dof_handler,
                                        dsp,
                                        state.constraints,
                                        false);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   state.owned,
                                                   state.comm,
                                                   state.relevant);
        matrix.reinit(state.owned, state.owned, dsp, state.comm);
      } // the pattern (0.4 kB/DoF) is freed before the cell map is built
      body.reinit(state, matrix);
      for (auto *v : {&residual, &body_residual, &direction, &point.velocity})
        v->reinit(state.owned, state.comm);
      ghost.reinit(state.owned, state.relevant, state.comm);
      factor_reuse.reinit(state.owned, state.comm);
      std::vector<unsigned int> held;
      for (const auto &f : state.force_controls)
        held.push_back(f.tool);
      forces.reinit(held, state.owned, state.comm);
      contact.reinit();
      linear_solver = create_linear_solver(prm.linear, prm.symmetric_tangent());
      linear_solver->time_phases(timer);
    }

    template <int dim>
    void FormingProblem<dim>::begin_step(const double step_dt)
    {
      dt = step_dt;
      body.begin_step();
      point.tangent   = true;
      penalty_updates = 0;
      corrections     = 0;
      step_max_linear = 0;
      step_condition  = 0;
    }

    template <int dim>
    void FormingProblem<dim>::begin_solve()
    {
      contact.begin_solve();
      factor_reuse.begin_solve();
      forces.begin_solve(state.control_velocities(), state.active_controls());
      iterate   = &state.velocity;
      direction = 0;
    }

    template <int dim>
    void FormingProblem<dim>::predict(VectorType &v)
    {
      if (prm.nonlinear.predictor == parameters::Predictor::keep_contact)
        {
          forces.move_tools(state.control_velocities(), state.tools);
          contact.predict(v, ghost, dt);
        }
    }

    template <int dim>
    double FormingProblem<dim>::assemble(const VectorType   &v,
                                         const Linearisation kind,
                                         const bool          with_tangent)
    {
      n_matrix_assemblies += with_tangent;
      const bool accepted = point.accepted && !point.tangent;
      point.kind          = kind;
      point.tangent       = with_tangent;
      ghost               = v;
      forces.move_tools(forces.trial_velocities(), state.tools);
      contact.search(ghost, dt);
      {
        // Separate sections: the cost per cell of each kind is measured
        // (doc/convergence.md).
        TimerOutput::Scope t(timer,
                             with_tangent ? "assembly: body, tangent"
                                          : "assembly: body, residual only");
        MatrixType        *K = with_tangent ? &matrix : nullptr;
        f_scale =
          accepted ? body.evaluate_accepted(state, ghost, dt, kind, K, residual)
                   : body.evaluate(state, ghost, dt, kind, K, residual);
      }
      // Factors: an adaptive strategy reads the body system (line-search
      // trials keep the factors of the iterate, and are estimated here only
      // when there are no factors for these pairs yet); others estimate at
      // every evaluation.
      bool estimate = !contact.reads_body_system();
      if (contact.reads_body_system() && with_tangent)
        {
          body_residual = residual;
          estimate      = !contact.has_factors();
        }
      if (estimate)
        contact.estimate(residual, matrix, dt, predictor());
      if (with_tangent)
        factor_reuse.assembled_at(v);
      add_contact_terms(with_tangent);
      return residual.l2_norm();
    }

    template <int dim>
    void FormingProblem<dim>::complete_tangent()
    {
      // The stress-velocity tangent of a point accepted since is linearised
      // about the iterate before it, as in an assembly before the
      // acceptance (BodyOperator::evaluate_accepted).
      if (!point.tangent)
        assemble(point.velocity, point.kind, true);
    }

    template <int dim>
    void FormingProblem<dim>::add_contact_terms(const bool with_tangent)
    {
      contact.add(with_tangent ? &matrix : nullptr,
                  &residual,
                  1.,
                  dt,
                  newton(point.kind));
      if (with_tangent)
        matrix_has_contact = true;
      if (controlled())
        {
          std::vector<double> targets;
          for (const auto &f : state.force_controls)
            targets.push_back(f.target);
          forces.assemble(state.contact_set,
                          contact.factors(),
                          state.tools,
                          prm.contact.regularisation_velocity,
                          dt,
                          newton(point.kind),
                          state.constraints,
                          targets);
        }
    }

    template <int dim>
    void FormingProblem<dim>::remove_contact_stiffness()
    {
      // The matrix holds K_b + K_c of the last assembly: the pairs, factors,
      // tools and linearisation it was made with are still those of the
      // state (no search and no estimate since).
      Assert(matrix_has_contact, ExcInternalError());
      contact.add(&matrix, nullptr, -1., dt, newton(point.kind));
      matrix_has_contact = false;
    }

    template <int dim>
    double FormingProblem<dim>::update_penalty()
    {
      if (!contact.reads_body_system())
        return -1;
      if (!point.tangent)
        {
          // Held factors: the residual of the point is already this one.
          if (contact.holds_factors(predictor()))
            return -1;
          complete_tangent();
        }
      remove_contact_stiffness();
      contact.estimate(body_residual, matrix, dt, predictor());
      // Newton estimates here once per accepted iterate, the predictor first.
      ++penalty_updates;
      residual = body_residual;
      // The copy leaves the vector in 'insert' mode; settle it on every rank
      // now, before ranks with and without contact pairs start adding.
      residual.compress(VectorOperation::insert);
      add_contact_terms(true);
      return residual.l2_norm();
    }

    template <int dim>
    void FormingProblem<dim>::end_solve()
    {
      if (!contact.reads_body_system())
        return;
      if (!point.tangent)
        {
          // The matrix is of the iterate before; the next solve assembles
          // anew, and only a strategy that reads it needs the tangent.
          if (!contact.reads_converged_system())
            return;
          complete_tangent();
        }
      // The body tangent for the strategy; the next solve assembles anew.
      remove_contact_stiffness();
      contact.converged(body_residual, matrix, dt);
    }

    template <int dim>
    Evaluation FormingProblem<dim>::evaluate(const double        alpha,
                                             const Linearisation kind,
                                             const bool          tangent_now)
    {
      point.velocity = *iterate;
      point.velocity.add(alpha, direction);
      point.accepted = false;
      forces.set_step_length(alpha);
      const double r        = assemble(point.velocity,
                                kind,
                                tangent_now || kind == Linearisation::exact);
      last_evaluation       = norms(r);
      last_evaluation.slope = directional_derivative(direction);
      return last_evaluation;
    }

    template <int dim>
    Direction FormingProblem<dim>::solve(const double tolerance)
    {
      linear_solver->set_forcing(tolerance);
      Direction d;
      direction           = 0;
      d.linear_iterations = solve_direction(direction);
      d.norm              = direction.l2_norm();
      VectorType full(*iterate);
      full.add(1., direction);
      d.full_step_norm = full.l2_norm();
      d.extra_relative = extra_correction();
      d.slope          = directional_derivative(direction);
      return d;
    }

    template <int dim>
    Accepted FormingProblem<dim>::accept()
    {
      *iterate       = point.velocity;
      point.accepted = true;
      forces.accept();
      body.accept(state.comm, prm.nonlinear.log_iterations);
      Accepted     a;
      const double r       = update_penalty();
      a.evaluation         = norms(r >= 0 ? r : last_evaluation.residual);
      a.active_set_changed = contact.changed();
      a.norm               = iterate->l2_norm();
      a.extra_relative     = extra_correction();
      return a;
    }

    template <int dim>
    bool FormingProblem<dim>::tighten(Evaluation &evaluation)
    {
      if (!contact.reads_body_system() || !contact.tighten())
        return false;
      complete_tangent();
      evaluation = norms(update_penalty());
      return true;
    }

    template <int dim>
    unsigned int FormingProblem<dim>::solve_direction(VectorType &dv)
    {
      complete_tangent();
      TimerOutput::Scope t(timer, "linear solve");
      VectorType         rhs(residual);
      rhs *= -1.;
      const unsigned long factorised = linear_solver->factorisations();
      if (prm.linear.condition_iterations > 0)
        step_condition = std::max(
          step_condition,
          estimate_condition(matrix, rhs, prm.linear.condition_iterations));
      // Bordered system (tools under force control): their columns
      // K z_j = b_j with the same factors, in the same solve. The first
      // correction of a step comes from the secant tangent (dual reset),
      // under which the sheet below the holder is 5-10x softer than in
      // Newton's: the Schur complement (e - c^T K^-1 b) is then 2e-4 e, and
      // du about 100x the holder's speed. The tools keep their velocities
      // for that one correction (doc/theory.md section 6a), and K^-1 b is
      // not needed.
      std::vector<unsigned int> bordered;
      for (unsigned int j = 0; j < forces.size(); ++j)
        if (forces.active(j) && forces.engaged(j) && corrections > 0)
          bordered.push_back(j);
        else
          forces.hold_or_close(j,
                               state.tools.allowed_penetration(forces.tool(j)),
                               dt);
      unsigned int its = 0;
      if (bordered.empty())
        its = linear_solver->solve(matrix, dv, rhs, factor_reuse.may_reuse());
      else
        {
          std::vector<VectorType> z(bordered.size(),
                                    VectorType(state.owned, state.comm));
          its = linear_solver->solve_pair(matrix,
                                          dv,
                                          rhs,
                                          z[0],
                                          forces.column(bordered[0]),
                                          factor_reuse.may_reuse());
          // More tools: more columns with the factors of this matrix.
          for (unsigned int i = 1; i < bordered.size(); ++i)
            its += linear_solver->solve(matrix,
                                        z[i],
                                        forces.column(bordered[i]),
                                        true);
          forces.correct(bordered, dv, z);
          for (unsigned int i = 0; i < bordered.size(); ++i)
            dv.add(forces.correction(bordered[i]), z[i]);
        }
      ++corrections;
      if (linear_solver->factorisations() != factorised)
        factor_reuse.factorised();
      n_factorisations += linear_solver->factorisations() - factorised;
      step_max_linear = std::max(step_max_linear, its);
      state.constraints.distribute(dv);
      return its;
    }

    template <int dim>
    double FormingProblem<dim>::extra_correction() const
    {
      double largest = 0;
      for (unsigned int j = 0; j < forces.size(); ++j)
        if (forces.active(j))
          largest = std::max(largest,
                             std::abs(forces.correction(j)) /
                               std::max(std::abs(forces.velocity(j)),
                                        state.tools.punch_speed()));
      return largest;
    }

    template <int dim>
    Evaluation FormingProblem<dim>::norms(const double r) const
    {
      Evaluation e;
      e.residual = r;
      // rho is a force (N), as the nodal entries of r.
      for (unsigned int j = 0; j < forces.size(); ++j)
        if (forces.active(j))
          {
            const double rho = std::abs(forces.residual(j));
            e.extra          = std::max(e.extra, rho);
            e.extra_relative =
              std::max(e.extra_relative, rho / state.force_controls[j].target);
          }
      e.scale = f_scale;
      return e;
    }

    template <int dim>
    double
    FormingProblem<dim>::directional_derivative(const VectorType &dv) const
    {
      // rho_j falls as u_j grows (e_j >= 0): -du_j rho_j, negative along a
      // Newton direction, as r . dv.
      double slope = residual * dv;
      for (unsigned int j = 0; j < forces.size(); ++j)
        if (forces.active(j))
          slope -= forces.correction(j) * forces.residual(j);
      return slope;
    }

    template <int dim>
    std::string FormingProblem<dim>::info() const
    {
      std::ostringstream s;
      s << contact.info();
      if (body.stress_velocity() && prm.nonlinear.log_iterations)
        {
          const auto &c = body.rigid_counts();
          s << "  rigid points: " << c[0] << " (+" << c[1] << "/-" << c[2]
            << ")";
        }
      for (unsigned int j = 0; j < forces.size(); ++j)
        if (forces.active(j))
          s << "  " << state.tools.key(forces.tool(j))
            << ": u=" << forces.velocity(j)
            << " mm/s, F-F_set=" << -forces.residual(j) << " N";
      return s.str();
    }

#define INSTANTIATE(dim) template class FormingProblem<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
