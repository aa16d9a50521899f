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
        , beads(prm, assembler.law(), state.kinematics)
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
      point.matrix = Iterate::Matrix::none;
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
      if (beads.any())
        {
          TimerOutput::Scope t(timer, "draw beads");
          beads.begin_step(state);
        }
      point.matrix    = Iterate::Matrix::none;
      iterates        = 0;
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
    double FormingProblem<dim>::assemble(const bool with_tangent)
    {
      ghost = point.velocity;
      contact.search(ghost,
                     forces.tool_velocities(point.tool_speeds, state.tools),
                     dt);
      evaluate_body(with_tangent);
      contact.at_point(body_system());
      add_contact_forces();
      return residual.l2_norm();
    }

    template <int dim>
    void FormingProblem<dim>::evaluate_body(const bool with_tangent)
    {
      // Separate sections: the cost per cell of each kind is measured
      // (doc/convergence.md).
      TimerOutput::Scope t(timer,
                           with_tangent ? "assembly: body, tangent"
                                        : "assembly: body, residual only");
      n_matrix_assemblies += with_tangent;
      MatrixType *K = with_tangent ? &matrix : nullptr;
      // A point accepted before its tangent was assembled is linearised
      // about the iterate before it (BodyOperator::evaluate_accepted).
      f_scale =
        point.accepted
          ? body
              .evaluate_accepted(state, ghost, dt, point.kind, K, body_residual)
          : body.evaluate(state, ghost, dt, point.kind, K, body_residual);
      point.matrix =
        with_tangent ? Iterate::Matrix::body : Iterate::Matrix::none;
      if (with_tangent)
        factor_reuse.assembled_at(point.velocity);
    }

    template <int dim>
    void FormingProblem<dim>::add_contact_forces()
    {
      residual = body_residual;
      // The copy leaves the vector in 'insert' mode; settle it on every rank
      // now, before ranks with and without contact pairs start adding.
      residual.compress(VectorOperation::insert);
      contact.add(nullptr, &residual, dt, newton(point.kind));
      add_beads(nullptr, &residual);
      if (controlled())
        {
          // The beads' opening force is taken from the holder's set force.
          std::vector<double> targets;
          for (const auto &f : state.force_controls)
            targets.push_back(f.tool == state.tools.holder_index()
                                ? std::max(f.target - beads.opening(), 0.)
                                : f.target);
          forces.assemble(contact.pairs(),
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
    void FormingProblem<dim>::add_beads(MatrixType *K, VectorType *r)
    {
      if (!beads.any())
        return;
      TimerOutput::Scope t(timer, "draw beads");
      beads.add(ghost,
                state.constraints,
                prm.contact.regularisation_velocity,
                newton(point.kind),
                K,
                r);
    }

    template <int dim>
    void FormingProblem<dim>::complete_tangent()
    {
      if (point.has_tangent())
        return;
      evaluate_body(true);
      add_contact_forces();
    }

    template <int dim>
    contact::SystemView FormingProblem<dim>::body_system()
    {
      return contact::SystemView(&body_residual,
                                 &matrix,
                                 &state.constraints,
                                 dt,
                                 predictor(),
                                 [this]() {
                                   // The contact stiffness enters the
                                   // matrix for the solve, after the
                                   // strategies' reads.
                                   Assert(point.matrix !=
                                            Iterate::Matrix::body_and_contact,
                                          ExcInternalError());
                                   if (point.has_tangent())
                                     return;
                                   // Timed as an assembly, not as the
                                   // estimate that asked for it.
                                   const auto section =
                                     ContactOperator<dim>::estimate_section;
                                   timer.leave_subsection(section);
                                   evaluate_body(true);
                                   timer.enter_subsection(section);
                                 });
    }

    template <int dim>
    double FormingProblem<dim>::update_penalty()
    {
      const bool had_tangent = point.has_tangent();
      const bool estimated   = contact.at_iterate(body_system());
      // The first accepted iterate of a step is its predictor.
      ++iterates;
      if (!estimated && point.has_tangent() == had_tangent)
        return -1;
      add_contact_forces();
      return residual.l2_norm();
    }

    template <int dim>
    void FormingProblem<dim>::end_solve()
    {
      contact.converged(body_system());
      if (beads.any())
        {
          auto records =
            beads.rates(ghost, prm.contact.regularisation_velocity, state.comm);
          for (unsigned int b = 0; b < records.size(); ++b)
            {
              records[b].work  = state.beads[b].work;
              records[b].drawn = state.beads[b].drawn;
            }
          state.beads = records;
        }
    }

    template <int dim>
    Evaluation FormingProblem<dim>::evaluate(const double        alpha,
                                             const Linearisation kind,
                                             const bool          tangent_now)
    {
      point.velocity = state.velocity;
      point.velocity.add(alpha, direction);
      point.tool_speeds = forces.speeds_at(alpha);
      point.kind        = kind;
      point.accepted    = false;
      const double r    = assemble(tangent_now || kind == Linearisation::exact);
      last_evaluation   = norms(r);
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
      VectorType full(state.velocity);
      full.add(1., direction);
      d.full_step_norm = full.l2_norm();
      d.extra_relative = extra_correction();
      d.slope          = directional_derivative(direction);
      return d;
    }

    template <int dim>
    Accepted FormingProblem<dim>::accept()
    {
      state.velocity = point.velocity;
      point.accepted = true;
      forces.accept(point.tool_speeds);
      forces.move_tools(point.tool_speeds, state.tools);
      contact.accept();
      body.accept(state.comm, prm.nonlinear.log_iterations);
      Accepted     a;
      const double r       = update_penalty();
      a.evaluation         = norms(r >= 0 ? r : last_evaluation.residual);
      a.active_set_changed = contact.changed();
      a.norm               = state.velocity.l2_norm();
      a.extra_relative     = extra_correction();
      return a;
    }

    template <int dim>
    bool FormingProblem<dim>::tighten(Evaluation &evaluation)
    {
      if (!contact.tighten())
        return false;
      const double r = update_penalty();
      evaluation     = norms(r >= 0 ? r : residual.l2_norm());
      return true;
    }

    template <int dim>
    unsigned int FormingProblem<dim>::solve_direction(VectorType &dv)
    {
      complete_tangent();
      if (point.matrix == Iterate::Matrix::body)
        {
          contact.add(&matrix, nullptr, dt, newton(point.kind));
          add_beads(&matrix, nullptr);
          point.matrix = Iterate::Matrix::body_and_contact;
        }
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
