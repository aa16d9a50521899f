#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/app/blas_kernel.h>
#include <formsolve/app/error_exit.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/material/material_summary.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/history_writer.h>
#include <formsolve/postprocess/progress.h>
#include <formsolve/refinement/adapt.h>
#include <formsolve/simulation/time_loop.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    TimeLoop<dim>::TimeLoop(const parameters::Run  &run,
                            const ParameterHandler &ph)
        : prm(run)
        , parameter_handler(ph)
        , comm(MPI_COMM_WORLD)
        , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
        // Rank 0's timings; no communicator, so an error on the way out of
        // run() cannot deadlock in the timer's destructor.
        , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
        , material(run.material)
        , damage(run.material, material.mean_r())
        , state(run, comm)
        , history_update(material,
                         state.kinematics,
                         state.reference_mapping,
                         run.mesh.degree,
                         &damage)
        , assembler(material,
                    state.kinematics,
                    state.reference_mapping,
                    run.mesh.degree)
        , step_solver(run, state, assembler, timer, pcout)
        , criteria(run.refinement,
                   state.tools,
                   geometry::initial_mesh_level(run.mesh))
        , sheet(run)
        , split(run.split, run.geometry.thickness)
    {}

    template <int dim>
    bool TimeLoop<dim>::adapt()
    {
      TimerOutput::Scope t(timer, "mesh refinement");
      // The transfer needs memory, and a new mesh drops the factors anyway:
      // free them then, and keep them (and their analysis) otherwise.
      const auto r =
        refinement::adapt_mesh(state, criteria, history_update, [this]() {
          step_solver.release_factors();
        });
      if (!r.changed)
        return false;
      forces_current = false;
      step_solver.reinit();
      auto &log = *refinement_log;
      log.set("step", state.step);
      log.set("punch_travel", state.tools.punch_travel());
      log.set("cells_before", r.cells_before);
      log.set("cells_after", r.cells_after);
      log.set("dofs", r.dofs);
      log.set("flagged_refine", r.refine);
      log.set("flagged_coarsen", r.coarsen);
      log.set("volume_before", r.volume_before);
      log.set("volume_after", r.volume_after);
      log.set("strain_integral_before", r.strain_before);
      log.set("strain_integral_after", r.strain_after);
      log.set("damage_integral_before", r.damage_before);
      log.set("damage_integral_after", r.damage_after);
      log.write_row();
      return true;
    }

    template <int dim>
    std::string TimeLoop<dim>::check_events()
    {
      auto              &tools  = state.tools;
      const unsigned int holder = tools.holder_index();
      state.update_contact_areas(); // which nodes face the holder
      std::ostringstream travel;
      travel << tools.punch_travel() << " mm";
      // The holder lets go of the blank when the flange under its face is
      // narrower than half the sheet thickness (the rim is at its inner
      // edge: pressing on, its edge would push the rim over the die radius),
      // or when no sheet node facing it is within reach any more. It stays
      // where it is.
      const bool narrow =
        holder != tools.none && !state.holder.released &&
        state.max_lateral_distance(holder) <= 0.5 * prm.geometry.thickness;
      if (holder != tools.none && !state.holder.released &&
          (narrow || state.min_distance(holder) > prm.contact.search_distance))
        {
          state.holder.released       = true;
          state.holder.release_travel = tools.punch_travel();
          if (auto *control = state.force_control(holder))
            {
              control->active   = false;
              control->velocity = 0;
            }
          tools.set_speed_along(holder, 0.);
          pcout << "blank holder released at punch travel " << travel.str()
                << (narrow ? ": the flange under it is narrower than half "
                             "the sheet thickness"
                           : ": no sheet within reach of it")
                << std::endl;
        }
      to_go = std::numeric_limits<double>::quiet_NaN();
      if (prm.time.end_of_run == parameters::EndOfRun::holder_release)
        {
          if (state.holder.released)
            return "the blank holder was released at punch travel " +
                   travel.str();
          to_go =
            state.max_lateral_distance(holder) - 0.5 * prm.geometry.thickness;
        }
      if (prm.time.end_of_run == parameters::EndOfRun::draw_through)
        {
          // Nodes touching the die wall sit at lateral distance 0 within the
          // penetration: a tolerance of 1 % of t0 counts them as inside.
          const double flange = state.max_lateral_distance(tools.die_index()) -
                                0.01 * prm.geometry.thickness;
          if (flange <= 0)
            return "drawn through: the whole blank lies inside the die "
                   "opening at punch travel " +
                   travel.str();
          to_go = flange;
        }
      return "";
    }

    template <int dim>
    void TimeLoop<dim>::start(const bool resume, RunSummary &summary)
    {
      if (resume)
        {
          const auto meta = checkpoint->load(state);
          step_solver.reinit();
          restore_loop(meta, summary);
        }
      else
        {
          make_part();
          step_solver.reinit();
          check_initial_scene();
        }
      prepare_output_directory();
      {
        Utilities::System::MemoryStats mem;
        Utilities::System::get_memory_stats(mem);
        summary.setup_memory_kb_max_rank =
          Utilities::MPI::max(double(mem.VmHWM), comm);
      }

      pcout << "formsolve: " << model::name(prm.geometry.model) << " model, "
            << Utilities::MPI::n_mpi_processes(comm) << " rank(s), "
            << state.tria.n_global_active_cells() << " cells, "
            << state.dof_handler.n_dofs() << " DoFs (Q" << prm.mesh.degree
            << ", " << prm.mesh.layers << " layers), contact "
            << step_solver.strategy_name() << ", forces scaled by "
            << prm.geometry.symmetry_factor() << " to the full part; BLAS "
            << app::blas_kernel() << "\n";
      for (const auto &line :
           material::material_summary(prm.material,
                                      material,
                                      damage,
                                      prm.geometry.thickness))
        pcout << line << "\n";
      if (const auto advice = app::blas_advice(); !advice.empty())
        pcout << "note: OpenBLAS runs its generic Prescott kernels on this "
                 "CPU, which makes the factorisations about 2x slower; start "
                 "formsolve with "
              << advice << " (scripts/formsolve-run does)\n";
      for (const auto &note : state.tools.notes())
        pcout << "note: " << note << "\n";
      if (earlier)
        pcout << "next operation: the part of " << earlier->folder << " ("
              << (earlier->sprung ? "sprung back" : "as formed") << ", after "
              << earlier->steps << " steps to punch travel " << earlier->travel
              << " mm: " << earlier->end_reason
              << "); tools and time start afresh" << std::endl;
      if (earlier && !earlier->trim_failure.empty())
        pcout << "warning: the trimming of that part failed ("
              << earlier->trim_failure << "); this run forms the untrimmed part"
              << std::endl;
      if (earlier && earlier->trimmed)
        {
          const auto &m = earlier->part_mesh;
          pcout << "trimmed part: on a mesh of its own, " << m.kept
                << " cells of the earlier mesh's level " << m.level
                << " without " << m.left_out
                << " cut away, the nodes next to the cut moved onto it by up "
                   "to "
                << m.largest_move << " mm, refined as the earlier mesh; volume "
                << earlier->volume
                << " mm^3 (the trimmed part's: " << earlier->earlier_volume
                << ")" << std::endl;
        }
      if (earlier && !earlier->split.empty())
        pcout << "warning: that part split in its run (" << earlier->split
              << "); this run forms a split part" << std::endl;
      if (resume)
        pcout << "resumed from the checkpoint at step " << state.step
              << ", punch travel " << state.tools.punch_travel() << " mm"
              << std::endl;

      history =
        std::make_unique<postprocess::HistoryWriter<dim>>(state,
                                                          resume
                                                            ? int(state.step)
                                                            : -1);
      if (prm.refinement.enabled())
        start_refinement(resume);
      if (!resume && prm.output.interval > 0)
        write_output();
      // A coarser mesh would average the earlier run's history.
      if (!resume && !earlier && state.step == 0 &&
          prm.nonlinear.first_step_start ==
            parameters::FirstStepStart::coarser_mesh)
        start_from_coarser_mesh(summary);
    }

    template <int dim>
    void TimeLoop<dim>::start_refinement(const bool resume)
    {
      refinement_log = std::make_unique<postprocess::StatisticsTable>(
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
                                 "strain_integral_after",
                                 "damage_integral_before",
                                 "damage_integral_after"},
        Utilities::MPI::this_mpi_process(comm) == 0,
        resume ? int(refinement_rows) : -1);
      if (resume)
        return;
      // Refine towards the radii before the first step, one level a pass.
      for (unsigned int pass = 0; pass < 8 && adapt(); ++pass)
        {}
      pcout << "adapted mesh: " << state.tria.n_global_active_cells()
            << " cells, " << state.dof_handler.n_dofs() << " DoFs" << std::endl;
    }

    template <int dim>
    solver::StepReport TimeLoop<dim>::solve_step(RunSummary &summary)
    {
      auto        &tools  = state.tools;
      const double stroke = tools.punch_stroke(), speed = tools.punch_speed();
      // The step ends at the stroke, and on each profile travel, so that a
      // profile is of the travel asked for.
      double max_dt = (stroke - tools.punch_travel()) / speed;
      for (const double p : prm.output.profile_travels)
        if (p > tools.punch_travel() + 1e-9)
          max_dt = std::min(max_dt, (p - tools.punch_travel()) / speed);
      if (const double p = split_stop_travel(); p > tools.punch_travel() + 1e-9)
        max_dt = std::min(max_dt, (p - tools.punch_travel()) / speed);
      const double newton_start = seconds();
      const auto   report       = step_solver.solve(max_dt);
      summary.newton_wall_time += seconds() - newton_start;
      summary.newton_iterations += report.iterations;
      summary.linear_iterations += report.linear_iterations;
      summary.matrix_assemblies += report.matrix_assemblies;
      summary.factorisations += report.factorisations;
      summary.factorisation_memory_mb =
        std::max(summary.factorisation_memory_mb,
                 report.factorisation_memory_mb);
      summary.factor_entries =
        std::max(summary.factor_entries, report.factor_entries);
      summary.cutbacks += report.cutbacks;
      return report;
    }

    template <int dim>
    void TimeLoop<dim>::note_ironing(const contact::ContactStatistics<dim> &s,
                                     const double punch_force,
                                     RunSummary  &summary)
    {
      const double f = prm.geometry.symmetry_factor() *
                       contact::ironing_force(s,
                                              state.tools.punch_index(),
                                              state.tools.die_index());
      if (f <= 0.005 * std::abs(punch_force))
        return;
      const double p               = contact::ironing_pressure(s,
                                                 state.tools.punch_index(),
                                                 state.tools.die_index());
      summary.max_ironing_force    = std::max(summary.max_ironing_force, f);
      summary.max_ironing_pressure = std::max(summary.max_ironing_pressure, p);
      if (summary.ironing_travel >= 0)
        return;
      summary.ironing_travel = s.force_travel;
      pcout << "note: the wall is ironed, squeezed between punch and die at "
            << p << " MPa from punch travel " << s.force_travel
            << " mm (history.csv: ironing_pressure)" << std::endl;
    }

    template <int dim>
    void TimeLoop<dim>::record_step(const solver::StepReport &report,
                                    RunSummary               &summary)
    {
      const auto stats = step_solver.statistics(report.dt);
      {
        TimerOutput::Scope t(timer, "state update");
        state.advance(report.dt,
                      history_update,
                      step_solver.forming_system().point_frames());
        forces_current = true;
        last_dt        = report.dt;
      }
      summary.steps = state.step;
      summary.n_dofs =
        std::max(summary.n_dofs, double(state.dof_handler.n_dofs()));
      summary.dof_steps += state.dof_handler.n_dofs();
      const double wall    = seconds();
      const auto   forming = measure_forming();
      history->write(state, report, stats, forming, wall);

      const double travel = state.tools.punch_travel();
      // The sheet's columns at the profile travels this step reached.
      for (const double p : prm.output.profile_travels)
        if (travel - report.dt * prm.tools.punch_speed < p - 1e-9 &&
            p <= travel + 1e-9)
          {
            std::ostringstream name;
            name << "sheet_" << p << "mm.csv";
            sheet.write_csv(comm, prm.output.directory, name.str());
          }
      const double force = prm.geometry.symmetry_factor() *
                           stats.tool_force[state.tools.punch_index()][dim - 1];
      if (force > summary.peak_punch_force)
        {
          summary.peak_punch_force  = force;
          summary.peak_force_travel = stats.force_travel;
        }
      summary.max_penetration =
        std::max(summary.max_penetration, stats.max_penetration);
      tool_loaded.resize(state.tools.size(), false);
      for (unsigned int t = 0; t < state.tools.size(); ++t)
        tool_loaded[t] = tool_loaded[t] || stats.tool_force[t].norm() > 0;
      note_ironing(stats, force, summary);
      const auto fracture = check_fracture(forming, summary);
      announce_split(split.observe(sheet, travel, force, fracture, comm));
      print_step(report, force, stats.max_penetration);
    }

    template <int dim>
    void TimeLoop<dim>::print_step(const solver::StepReport &report,
                                   const double              force,
                                   const double              penetration)
    {
      const double wall = seconds();
      progress.record(wall, state.tools.punch_travel(), to_go);
      // The run ends at the stroke, past the split, or when the flange has
      // left the die: by its recent draw-in, and half the die radius more
      // for the rim to round it (doc/user-guide.md, section 5.3).
      const auto  &die = prm.tools.die;
      const double end =
        std::min({state.tools.punch_stroke(),
                  split_stop_travel(),
                  progress.end_travel(die.shape == parameters::ToolShape::mesh
                                        ? 0.
                                        : 0.5 * die.profile_radius)});
      const auto &sh = sheet.summary();
      pcout << "step " << std::setw(4) << state.step << "  t=" << std::fixed
            << std::setprecision(3) << state.time
            << " s  travel=" << state.tools.punch_travel()
            << " mm  F=" << std::setprecision(2) << force / 1000.
            << " kN  thin=" << std::setprecision(1) << sh.max_thinning
            << " %  FLC margin=" << sh.flc_margin
            << " %  newton=" << std::setw(2) << report.iterations
            << (report.cutbacks > 0 ? "  cut=" + std::to_string(report.cutbacks)
                                    : std::string())
            << "  pen=" << std::scientific << std::setprecision(2)
            << penetration
            << " mm  wall=" << postprocess::Progress::duration(wall)
            << "  left~"
            << postprocess::Progress::duration(progress.time_left(end))
            << std::defaultfloat << std::setprecision(6) << std::endl;
    }

#define INSTANTIATE(dim) template class TimeLoop<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
