#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/output/vtu_writer.h>
#include <formsolve/simulation/history_file.h>
#include <formsolve/simulation/simulation.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    Simulation<dim>::Simulation(const parameters::Run  &run,
                                const ParameterHandler &ph)
        : prm(run)
        , parameter_handler(ph)
        , comm(MPI_COMM_WORLD)
        , pcout(std::cout,
                Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        // Rank 0's timings; no communicator, so an error on the way out of
        // run() cannot deadlock in the timer's destructor.
        , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
        , tria(comm)
        , fe(FE_Q<dim>(run.mesh.degree), dim)
        , dof_handler(tria)
        , reference_mapping(run.mesh.degree)
        , material(run.material)
        , assembler(material, reference_mapping, run.mesh.degree)
        , tools(run.tools, run.contact, run.geometry.thickness)
        , contact_post(run.contact.search_distance,
                       run.contact.regularisation_velocity,
                       run.contact.max_status_flips)
        , estimator(contact::create_penalty_estimator<dim>(run.contact))
        , refinement(run.refinement, tools)
    {}

    template <int dim>
    void Simulation<dim>::setup_mesh_and_dofs()
    {
      TimerOutput::Scope t(timer, "setup");
      geometry::create_blank_mesh(prm.geometry, prm.mesh, tria);
      setup_dofs();
    }

    template <int dim>
    void Simulation<dim>::setup_dofs()
    {
      // The direct solver refers to the matrix: release it first.
      linear_solver.reset();
      mapping.reset();
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

      constraints.clear();
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      // Symmetry planes: no velocity normal to the plane.
      const Functions::ZeroFunction<dim> zero(dim);
      if (prm.geometry.symmetric_in_x())
        VectorTools::interpolate_boundary_values(
          reference_mapping,
          dof_handler,
          geometry::symmetry_x,
          zero,
          constraints,
          fe.component_mask(FEValuesExtractors::Scalar(0)));
      if (prm.geometry.symmetric_in_y())
        VectorTools::interpolate_boundary_values(
          reference_mapping,
          dof_handler,
          geometry::symmetry_y,
          zero,
          constraints,
          fe.component_mask(FEValuesExtractors::Scalar(1)));
      constraints.close();

      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      matrix.reinit(owned, owned, dsp, comm);

      if (estimator->needs_system())
        body_matrix.reinit(matrix);
      residual.reinit(owned, comm);
      body_residual.reinit(owned, comm);
      velocity.reinit(owned, comm);
      displacement.reinit(owned, comm);
      contact_fields.reinit(owned, comm);
      velocity_ghost.reinit(owned, relevant, comm);
      displacement_ghost.reinit(owned, relevant, comm);
      mapping =
        std::make_unique<MappingQEulerian<dim, VectorType>>(prm.mesh.degree,
                                                            dof_handler,
                                                            displacement_ghost);

      history.clear();
      assembler.initialize_history(dof_handler, history);
      contact_post.setup(dof_handler, reference_mapping, contact_set);
      epsilon.clear();
      last_active.clear();
      estimator->reset();

      std::vector<std::vector<bool>> modes;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       modes);
      linear_solver = std::make_unique<solver::LinearSolver>(prm.linear, modes);
    }

    template <int dim>
    bool Simulation<dim>::adapt_mesh(const unsigned int step)
    {
      TimerOutput::Scope t(timer, "mesh refinement");
      velocity_ghost = velocity;
      const auto flags =
        refinement.mark(dof_handler, *mapping, velocity_ghost, tools);
      if (flags.refine + flags.coarsen == 0)
        return false;
      const double volume_before = assembler.volume(dof_handler, *mapping);
      const double strain_before =
        assembler.strain_integral(dof_handler, *mapping, history);
      const double cells_before = tria.n_global_active_cells();

      // Smoothing drops coarsening flags of incomplete families (and adds
      // refinement for the 2:1 balance): count what is left.
      tria.prepare_coarsening_and_refinement();
      unsigned int left = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (cell->refine_flag_set() || cell->coarsen_flag_set()))
          ++left;
      if (Utilities::MPI::sum(left, comm) == 0)
        return false;
      parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
        dof_handler);
      const std::vector<const VectorType *> in = {&velocity_ghost,
                                                  &displacement_ghost};
      transfer.prepare_for_coarsening_and_refinement(in);
      // History: L2 projection onto discontinuous Q_p per cell, which keeps
      // cell integrals when cells are split or merged.
      const FE_DGQ<dim> projection(prm.mesh.degree);
      parallel::distributed::
        ContinuousQuadratureDataTransfer<dim, QuadraturePointHistory>
          history_transfer(projection,
                           assembler.quadrature(),
                           assembler.quadrature());
      store_parent_history(tria, assembler.quadrature(), history);
      history_transfer.prepare_for_coarsening_and_refinement(tria, history);
      mapping.reset();
      tria.execute_coarsening_and_refinement();

      setup_dofs();
      std::vector<VectorType *> out = {&velocity, &displacement};
      transfer.interpolate(out);
      constraints.distribute(velocity);
      constraints.distribute(displacement);
      velocity_ghost     = velocity;
      displacement_ghost = displacement;
      history_transfer.interpolate();
      contact_post.update_areas(dof_handler, *mapping, contact_set);

      const double volume_after = assembler.volume(dof_handler, *mapping);
      const double strain_after =
        assembler.strain_integral(dof_handler, *mapping, history);
      if (refinement_log)
        refinement_log->write_row({double(step),
                                   tools.punch_travel(),
                                   cells_before,
                                   double(tria.n_global_active_cells()),
                                   double(dof_handler.n_dofs()),
                                   double(flags.refine),
                                   double(flags.coarsen),
                                   volume_before,
                                   volume_after,
                                   strain_before,
                                   strain_after});
      return true;
    }

    template <int dim>
    void Simulation<dim>::check_initial_scene()
    {
      contact_post.evaluate(tools,
                            displacement_ghost,
                            velocity_ghost,
                            0.,
                            contact_set);
      const double tol = 1e-6 * prm.geometry.thickness;
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          double worst = 0;
          for (const auto &p : contact_set.pairs)
            if (p.tool == t)
              worst = std::max(worst, -p.gap);
          worst = Utilities::MPI::max(worst, comm);
          std::ostringstream s;
          s << "Tools/" << tools[t].name()
            << ": the blank starts inside this tool (" << worst
            << " mm deep); check its Gap, Diameter and Profile radius "
            << "against Geometry";
          AssertThrow(worst <= tol, ExcMessage(s.str()));
        }
    }

    template <int dim>
    void Simulation<dim>::prepare_output_directory()
    {
      const std::string &dir = prm.output.directory;
      int                ok  = 1;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::error_code ec;
          std::filesystem::create_directories(dir, ec);
          const std::string probe = dir + "/.formsolve-write-test";
          ok                      = !ec && std::ofstream(probe).good();
          std::filesystem::remove(probe, ec);
          if (ok)
            parameter_handler.print_parameters(dir + "/parameters.prm",
                                               ParameterHandler::PRM);
        }
      ok = Utilities::MPI::min(ok, comm);
      AssertThrow(ok,
                  ExcMessage(
                    "Output/Output directory: cannot create or write '" + dir +
                    "'"));
    }

    template <int dim>
    double Simulation<dim>::assemble(const VectorType &v, const bool newton)
    {
      velocity_ghost = v;
      {
        TimerOutput::Scope t(timer, "contact");
        contact_post.evaluate(tools,
                              displacement_ghost,
                              velocity_ghost,
                              dt,
                              contact_set);
      }
      // Body first: an adaptive estimator reads its residual and tangent;
      // then the factors, then the contact terms with them.
      {
        TimerOutput::Scope t(timer, "assembly");
        f_scale = assembler.assemble_body(dof_handler,
                                          *mapping,
                                          constraints,
                                          velocity_ghost,
                                          history,
                                          dt,
                                          newton,
                                          &matrix,
                                          residual);
      }
      bool estimate = true;
      if (estimator->needs_system())
        {
          // Keep the body system for update_penalty(); estimate here only when
          // there are no factors for these pairs yet.
          body_matrix.copy_from(matrix);
          body_residual = residual;
          // The estimate is collective: decide on all ranks alike.
          estimate =
            Utilities::MPI::max(int(epsilon.size() != contact_set.pairs.size()),
                                comm) != 0;
        }
      if (estimate)
        estimate_penalty(residual, matrix);
      last_newton = newton;
      add_contact_terms();
      return residual.l2_norm();
    }

    template <int dim>
    void Simulation<dim>::estimate_penalty(const VectorType         &r_b,
                                           const solver::MatrixType &K_b)
    {
      TimerOutput::Scope t(timer, "penalty estimate");
      estimator->estimate(contact_set,
                          tools,
                          contact::SystemView{&r_b, &K_b, &constraints, dt},
                          epsilon);
    }

    template <int dim>
    void Simulation<dim>::add_contact_terms()
    {
      TimerOutput::Scope        t(timer, "assembly");
      solver::ContactInput<dim> contact{&contact_set,
                                        &epsilon,
                                        &tools,
                                        prm.contact.regularisation_velocity};
      assembler
        .add_contact(constraints, dt, contact, last_newton, &matrix, residual);
    }

    template <int dim>
    double Simulation<dim>::update_penalty()
    {
      if (!estimator->needs_system())
        return -1;
      estimate_penalty(body_residual, body_matrix);
      matrix.copy_from(body_matrix);
      residual = body_residual;
      // The copy leaves the vector in 'insert' mode; settle it on every rank
      // now, before ranks with and without contact pairs start adding.
      residual.compress(VectorOperation::insert);
      add_contact_terms();
      return residual.l2_norm();
    }

    template <int dim>
    unsigned int Simulation<dim>::solve(VectorType &dv)
    {
      TimerOutput::Scope t(timer, "linear solve");
      VectorType         rhs(residual);
      rhs *= -1.;
      const unsigned int its     = linear_solver->solve(matrix, dv, rhs);
      step_max_linear_iterations = std::max(step_max_linear_iterations, its);
      step_condition =
        std::max(step_condition, linear_solver->condition_estimate());
      constraints.distribute(dv);
      return its;
    }

    template <int dim>
    bool Simulation<dim>::contact_set_changed()
    {
      std::vector<bool> active(contact_set.pairs.size());
      // Locked pairs (chatter guard) do not count as changes.
      for (unsigned int k = 0; k < active.size(); ++k)
        active[k] = contact_set.pairs[k].active || contact_set.pairs[k].locked;
      const int changed = (active != last_active);
      last_active       = active;
      return Utilities::MPI::max(changed, comm) != 0;
    }

    template <int dim>
    void Simulation<dim>::fill_contact_fields()
    {
      // Component 0: smallest predicted gap (capped at the search distance),
      // 1: contact pressure, 2: penalty factor of the active pairs.
      // Accumulate per node first: mixing set and add on a Trilinos vector
      // triggers a collective exchange that ranks would reach unevenly.
      const unsigned int  n = contact_set.nodes.size();
      std::vector<double> gap(n, prm.contact.search_distance), pressure(n, 0.),
        penalty(n, 0.);
      for (unsigned int k = 0; k < contact_set.pairs.size(); ++k)
        {
          const auto &p = contact_set.pairs[k];
          gap[p.node]   = std::min(gap[p.node], p.predicted_gap);
          if (p.active)
            {
              pressure[p.node] += epsilon[k] * (p.shift - p.predicted_gap) /
                                  std::max(p.area, 1e-300);
              penalty[p.node] += epsilon[k];
            }
        }
      contact_fields = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          const auto &dofs        = contact_set.nodes[j].dofs;
          contact_fields[dofs[0]] = gap[j];
          contact_fields[dofs[1]] = pressure[j];
          contact_fields[dofs[2]] = penalty[j];
        }
      contact_fields.compress(VectorOperation::insert);
    }

    template <int dim>
    void Simulation<dim>::validate_scene()
    {
      setup_mesh_and_dofs();
      check_initial_scene();
      pcout << "input valid: " << tria.n_global_active_cells() << " cells, "
            << dof_handler.n_dofs() << " DoFs, " << tools.size() << " tool(s)"
            << std::endl;
    }

    template <int dim>
    RunSummary Simulation<dim>::run()
    {
      using Clock        = std::chrono::steady_clock;
      const auto start   = Clock::now();
      auto       seconds = [&]() {
        return std::chrono::duration<double>(Clock::now() - start).count();
      };

      setup_mesh_and_dofs();
      check_initial_scene();
      prepare_output_directory();

      const double sym = prm.geometry.symmetry_factor();
      pcout << "formsolve: " << Utilities::MPI::n_mpi_processes(comm)
            << " rank(s), " << tria.n_global_active_cells() << " cells, "
            << dof_handler.n_dofs() << " DoFs (Q" << prm.mesh.degree << ", "
            << prm.mesh.layers << " layers), forces scaled by " << sym
            << " to the full part\n";

      std::vector<std::string> columns = {"step",
                                          "time",
                                          "punch_travel",
                                          "punch_force",
                                          "max_penetration",
                                          "newton_iterations",
                                          "linear_iterations",
                                          "wall_time"};
      for (unsigned int t = 0; t < tools.size(); ++t)
        columns.push_back("force_" + tools.key(t));
      columns.insert(
        columns.end(),
        {"volume", "mean_penetration", "active_contacts", "picard_iterations"});
      for (unsigned int t = 0; t < tools.size(); ++t)
        columns.push_back("max_penetration_" + tools.key(t));
      columns.insert(columns.end(),
                     {"pairs_over_allowed",
                      "locked_pairs",
                      "strict_passes",
                      "min_penalty",
                      "max_penalty",
                      "max_linear_iterations",
                      "condition_estimate",
                      "dofs"});
      HistoryFile            history_file(prm.output.directory + "/history.csv",
                               columns,
                               Utilities::MPI::this_mpi_process(comm) == 0);
      output::VtuWriter<dim> writer(prm.output.directory);
      auto write = [&](const unsigned int step, const double time) {
        TimerOutput::Scope t(timer, "output");
        velocity_ghost = velocity;
        fill_contact_fields();
        VectorType contact_ghost(owned, relevant, comm);
        contact_ghost = contact_fields;
        output::OutputFields<dim> f{&velocity_ghost,
                                    &displacement_ghost,
                                    &contact_ghost,
                                    &history};
        writer.write(step, time, dof_handler, *mapping, f);
      };
      if (prm.refinement.enabled())
        {
          refinement_log = std::make_unique<HistoryFile>(
            prm.output.directory + "/refinement.csv",
            std::vector<std::string>{"step",
                                     "punch_travel",
                                     "cells_before",
                                     "cells_after",
                                     "dofs",
                                     "flagged_refine",
                                     "flagged_coarsen",
                                     "volume_before",
                                     "volume_after",
                                     "strain_integral_before",
                                     "strain_integral_after"},
            Utilities::MPI::this_mpi_process(comm) == 0);
          // Refine towards the radii before the first step, one level a pass.
          for (unsigned int pass = 0; pass < 8 && adapt_mesh(0); ++pass)
            {}
          pcout << "adapted mesh: " << tria.n_global_active_cells()
                << " cells, " << dof_handler.n_dofs() << " DoFs" << std::endl;
        }
      if (prm.output.interval > 0)
        write(0, 0.);

      const solver::NewtonSolver newton(
        prm.nonlinear,
        ConditionalOStream(std::cout,
                           pcout.is_active() && prm.nonlinear.log_iterations));
      RunSummary summary;
      summary.n_dofs      = dof_handler.n_dofs();
      double       time   = 0;
      unsigned int step   = 0;
      const double stroke = tools.punch_stroke(), speed = tools.punch_speed();
      while (tools.punch_travel() < stroke * (1 - 1e-12))
        {
          ++step;
          if (prm.refinement.enabled() && step > 1 &&
              (step - 1) % prm.refinement.interval == 0)
            adapt_mesh(step);
          summary.n_dofs =
            std::max(summary.n_dofs, double(dof_handler.n_dofs()));
          summary.dof_steps += dof_handler.n_dofs();
          dt = std::min(prm.time.time_step,
                        (stroke - tools.punch_travel()) / speed);
          {
            TimerOutput::Scope t(timer, "contact");
            contact_post.update_areas(dof_handler, *mapping, contact_set);
          }
          constraints.distribute(
            velocity); // previous step's velocity: predictor
          const double newton_start  = seconds();
          step_max_linear_iterations = 0;
          step_condition             = 0;
          solver::NewtonReport report;
          unsigned int         passes = 0;
          for (;; ++passes)
            {
              // A pass starts with fresh status memory (chatter guard).
              contact_set.begin_step();
              const auto r     = newton.solve(*this, velocity);
              report.converged = r.converged;
              report.failure   = r.failure;
              report.residual  = r.residual;
              report.iterations += r.iterations;
              report.linear_iterations += r.linear_iterations;
              report.picard_iterations += r.picard_iterations;
              // adaptive-strict: solve again while a node is deeper than delta.
              // augmented-lagrangian: update the multipliers, likewise.
              if (!r.converged ||
                  !estimator->finish_step(contact_set, tools, comm) ||
                  passes >= prm.contact.max_strict_passes)
                break;
            }
          summary.newton_wall_time += seconds() - newton_start;
          if (!report.converged)
            {
              std::ostringstream s;
              s << "step " << step << " (punch travel " << tools.punch_travel()
                << " mm): " << report.failure << " after " << report.iterations
                << " iterations (|r|/|f| = " << report.residual
                << "); results up to the previous step are in "
                << prm.output.directory;
              AssertThrow(false, ExcMessage(s.str()));
            }

          // The state at the converged velocity (contact_set and epsilon are
          // those of the last assembly, i.e. of this velocity).
          const auto stats =
            contact_post.statistics(tools, contact_set, epsilon, dt, comm);
          velocity_ghost = velocity;
          {
            TimerOutput::Scope t(timer, "state update");
            assembler.update_history(dof_handler,
                                     *mapping,
                                     velocity_ghost,
                                     dt,
                                     history);
            displacement.add(dt, velocity);
            displacement_ghost = displacement;
            tools.advance(dt);
            time += dt;
          }
          const double volume = assembler.volume(dof_handler, *mapping);

          summary.steps = step;
          summary.newton_iterations += report.iterations;
          summary.linear_iterations += report.linear_iterations;
          const double wall   = seconds();
          const double travel = tools.punch_travel();
          // Axial (z) forces of the sheet on the tools, full part, pressing =
          // +.
          const double        punch_force = sym * stats.tool_force[0][dim - 1];
          std::vector<double> row         = {double(step),
                                             time,
                                             travel,
                                             punch_force,
                                             stats.max_penetration,
                                             double(report.iterations),
                                             double(report.linear_iterations),
                                     prm.output.wall_time_in_history ? wall
                                                                             : 0.};
          for (unsigned int t = 0; t < tools.size(); ++t)
            row.push_back(sym * std::abs(stats.tool_force[t][dim - 1]));
          row.insert(row.end(),
                     {sym * volume,
                      stats.mean_penetration,
                      double(stats.n_active),
                      double(report.picard_iterations)});
          for (unsigned int t = 0; t < tools.size(); ++t)
            row.push_back(stats.tool_max_penetration[t]);
          double eps_min = std::numeric_limits<double>::max(), eps_max = 0;
          for (unsigned int k = 0; k < contact_set.pairs.size(); ++k)
            if (contact_set.pairs[k].active)
              {
                eps_min = std::min(eps_min, epsilon[k]);
                eps_max = std::max(eps_max, epsilon[k]);
              }
          eps_min = Utilities::MPI::min(eps_min, comm);
          eps_max = Utilities::MPI::max(eps_max, comm);
          row.insert(row.end(),
                     {double(stats.n_over_allowed),
                      double(stats.n_locked),
                      double(passes),
                      stats.n_active > 0 ? eps_min : 0.,
                      eps_max,
                      double(step_max_linear_iterations),
                      step_condition,
                      double(dof_handler.n_dofs())});
          history_file.write_row(row);

          const double left = wall / travel * (stroke - travel);
          pcout << "step " << std::setw(4) << step << "  t=" << std::fixed
                << std::setprecision(3) << time << " s  travel=" << travel
                << " mm  F=" << std::setprecision(2) << punch_force / 1000.
                << " kN  newton=" << std::setw(2) << report.iterations
                << "  pen=" << std::scientific << std::setprecision(2)
                << stats.max_penetration << " mm  wall=" << std::fixed
                << std::setprecision(1) << wall << " s  left~" << left << " s"
                << std::defaultfloat << std::endl;

          const bool last = tools.punch_travel() >= stroke * (1 - 1e-12);
          if (prm.output.interval > 0 &&
              (step % prm.output.interval == 0 || last))
            write(step, time);
        }

      summary.wall_time = seconds();
      {
        Utilities::System::MemoryStats m;
        Utilities::System::get_memory_stats(m);
        summary.peak_memory_kb = Utilities::MPI::sum(double(m.VmHWM), comm);
      }
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          // Machine-readable totals for benchmarks (doc/performance.md).
          std::ofstream f(prm.output.directory + "/run-summary.txt");
          f << "ranks = " << Utilities::MPI::n_mpi_processes(comm)
            << "\ndofs = " << summary.n_dofs << "\nmean_dofs = "
            << summary.dof_steps / std::max(1u, summary.steps)
            << "\ncells = " << tria.n_global_active_cells()
            << "\nsteps = " << summary.steps
            << "\nnewton_iterations = " << summary.newton_iterations
            << "\nlinear_iterations = " << summary.linear_iterations
            << "\nwall_time = " << summary.wall_time
            << "\nnewton_wall_time = " << summary.newton_wall_time
            << "\npeak_memory_kb_all_ranks = " << summary.peak_memory_kb
            << "\n";
        }
      pcout << "done: " << step << " steps, " << summary.newton_iterations
            << " Newton iterations, " << summary.linear_iterations
            << " linear iterations, " << summary.wall_time << " s; results in "
            << prm.output.directory << std::endl;
      timer.print_summary();
      return summary;
    }

    template class Simulation<3>;
  } // namespace simulation
} // namespace formsolve
