// How a run ends: the steps up to the stroke, an event, the split (and a
// little past it), or a step the solver cannot take; and the closing files
// every stop leaves (last VTU, sheet.csv, run-summary.txt, the report),
// also after an error past the first step.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/app/error_exit.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/time_loop.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;
    using postprocess::SplitMeasure;

    namespace
    {
      std::string mm(const double x)
      {
        std::ostringstream s;
        s.precision(4);
        s << x << " mm";
        return s.str();
      }
    } // namespace

    template <int dim>
    RunSummary TimeLoop<dim>::run(const bool resume)
    {
      RunSummary summary;
      start_time  = std::chrono::steady_clock::now();
      wall_before = &summary.wall_before;
      checkpoint  = std::make_unique<Checkpoint<dim>>(prm.output.directory,
                                                     parameter_listing());
      writer      = std::make_unique<postprocess::VtuWriter<dim>>(prm.output);
      tool_writer =
        std::make_unique<postprocess::ToolWriter<dim>>(prm.output.directory);
      start(resume, summary);
      summary.n_dofs =
        std::max(summary.n_dofs, double(state.dof_handler.n_dofs()));
      last_checkpoint = seconds();
      try
        {
          run_steps(summary);
        }
      catch (const std::exception &e)
        {
          // Past the first step there are results to close; before it, the
          // error is the whole story.
          if (state.step > 0)
            close_after_error(summary, app::exception_text(e));
          throw;
        }
      finish(summary);
      AssertThrow(!summary.solver_failed || split.split(),
                  ExcMessage(summary.end_reason +
                             "; the results up to the last converged step, "
                             "run-summary.txt, sheet.csv, a checkpoint and "
                             "the report are in " +
                             prm.output.directory));
      return summary;
    }

    template <int dim>
    void TimeLoop<dim>::run_steps(RunSummary &summary)
    {
      check_events(); // to_go at the start
      progress.record(seconds(), state.tools.punch_travel(), to_go);
      summary.end_reason  = "the punch stroke was reached";
      const double stroke = state.tools.punch_stroke();
      while (state.tools.punch_travel() < stroke * (1 - 1e-12))
        {
          if (prm.refinement.enabled() && state.step > 0 &&
              state.step % prm.refinement.interval == 0)
            adapt();
          if (const auto reason = check_events(); !reason.empty())
            {
              summary.end_reason = reason;
              return;
            }
          app::injected_failure(state.step + 1);
          app::injected_kill("step", state.step + 1);
          const auto report = solve_step(summary);
          if (!report.converged)
            {
              summary.solver_failed = true;
              summary.end_reason    = failure_reason(report);
              return;
            }
          record_step(report, summary);

          const double travel = state.tools.punch_travel();
          const bool   last   = travel >= stroke * (1 - 1e-12);
          const bool   stop   = travel >= split_stop_travel() - 1e-9;
          if (prm.output.interval > 0 &&
              (state.step % prm.output.interval == 0 || last))
            write_output();
          if (!last && !stop && checkpoint_due())
            save_checkpoint(summary);
          if (stop)
            {
              summary.end_reason = split_reason();
              return;
            }
        }
    }

    template <int dim>
    bool TimeLoop<dim>::checkpoint_due() const
    {
      const auto &o = prm.output;
      if (o.checkpoint_interval > 0 && state.step % o.checkpoint_interval == 0)
        return true;
      // Rank 0's clock decides for every rank.
      const int due = o.checkpoint_minutes > 0 &&
                      seconds() - last_checkpoint >= 60 * o.checkpoint_minutes;
      return Utilities::MPI::broadcast(comm, due, 0) != 0;
    }

    template <int dim>
    double TimeLoop<dim>::split_stop_travel() const
    {
      if (prm.split.after != parameters::AfterSplit::stop || !split.split())
        return std::numeric_limits<double>::infinity();
      return split.first().travel + prm.split.travel_past;
    }

    namespace
    {
      /// What a split measure found, in words.
      template <int dim>
      std::string what(const SplitMeasure                  m,
                       const postprocess::SplitEvent<dim> &e,
                       const parameters::Material         &material)
      {
        std::ostringstream s;
        s.precision(3);
        if (m == SplitMeasure::forming_limit)
          s << "the forming limit curve is reached";
        else if (m == SplitMeasure::neck && std::isfinite(e.value))
          s << "a neck forms (the thinnest column thins " << e.value
            << " times faster than its neighbours while the punch force "
               "falls)";
        else if (m == SplitMeasure::neck)
          s << "a neck forms (the thinnest column thins while its "
               "neighbours no longer do and the punch force falls)";
        else
          s << (material.fracture == parameters::FractureCriterion::oyane
                  ? "Oyane's integral"
                  : "the Cockcroft-Latham criterion")
            << " reaches 1 ("
            << (material.fracture_measure == parameters::FractureMeasure::local
                  ? "local maximum"
                  : "through-thickness average")
            << ")";
        return s.str();
      }
    } // namespace

    template <int dim>
    void TimeLoop<dim>::announce_split(const std::vector<SplitMeasure> &found)
    {
      for (const auto m : found)
        {
          const auto &e = split.event(m);
          const bool  first =
            !split_said && split.marks_split(m) && split.split_measure() == m;
          if (m == SplitMeasure::fracture && !first)
            continue; // check_fracture has said it
          std::ostringstream s;
          s << (first ? "split: " : "note: ") << what<dim>(m, e, prm.material)
            << " at punch travel " << mm(e.travel) << ", at "
            << e.where(prm.geometry.model);
          if (!split.marks_split(m))
            s << " (not a split by Split/Measures)";
          if (first)
            s << (prm.split.after == parameters::AfterSplit::stop
                    ? "; the run stops at punch travel " +
                        mm(split_stop_travel()) +
                        " (Split/Travel past the split)"
                    : std::string("; the run goes on (Split/After a split = "
                                  "continue)"));
          pcout << s.str() << std::endl;
          split_said = split_said || first;
        }
    }

    template <int dim>
    std::string TimeLoop<dim>::split_reason() const
    {
      const auto        &e = split.first();
      std::ostringstream s;
      s << "the sheet split: "
        << what<dim>(split.split_measure(), e, prm.material)
        << " at punch travel " << mm(e.travel) << ", at "
        << e.where(prm.geometry.model) << "; stopped "
        << mm(state.tools.punch_travel() - e.travel)
        << " past it (Split/After a split = stop)";
      return s.str();
    }

    template <int dim>
    std::string
    TimeLoop<dim>::failure_reason(const solver::StepReport &report) const
    {
      std::ostringstream s;
      if (split.split())
        {
          const auto &e = split.first();
          s << "the solver stopped converging "
            << mm(state.tools.punch_travel() - e.travel)
            << " of punch travel after the sheet split ("
            << what<dim>(split.split_measure(), e, prm.material) << " at "
            << mm(e.travel) << ", at " << e.where(prm.geometry.model)
            << "), which is the likely cause: ";
        }
      s << "step " << state.step + 1 << " (punch travel "
        << state.tools.punch_travel() << " mm): " << report.failure
        << " (|r|/|f| = " << report.residual << ") after " << report.cutbacks
        << " time-step cut(s), at the minimum time step (Time "
           "stepping/Minimum time step = "
        << prm.time.minimum_time_step << " s)";
      return s.str();
    }

    template <int dim>
    void TimeLoop<dim>::finish(RunSummary &summary)
    {
      if (prm.output.interval > 0)
        write_output(/*last=*/true);

      summary.wall_time = seconds();
      sheet.measure(state, damage);
      sheet.write_csv(comm, prm.output.directory);
      // Ears are the rim of a drawn cup: before draw-through the rim is
      // still the flange's, whose draw-in sheet.csv gives.
      if constexpr (dim == 3)
        if (prm.geometry.blank_shape == parameters::BlankShape::round &&
            summary.end_reason.rfind("drawn through", 0) == 0)
          {
            earing = postprocess::earing_profile(
              sheet.gathered_columns(comm),
              prm.geometry.model,
              prm.material.anisotropy.rolling_direction);
            postprocess::write_earing(earing, prm.output.directory);
          }
      // The part after forming: the forming's results above are the
      // untrimmed part's, on its mesh.
      if (prm.trimming.any() && !summary.solver_failed)
        trim();
      if (prm.springback.enabled && !summary.solver_failed &&
          trim_failure.empty())
        spring_back();
      save_checkpoint(summary, /*end=*/true);
      measure_memory(summary);
      write_summary(summary);
      pcout << "done: " << state.step << " steps, " << summary.newton_iterations
            << " Newton iterations, " << summary.cutbacks
            << " time-step cut(s), " << summary.linear_iterations
            << " linear solves/iterations, "
            << postprocess::Progress::duration(summary.wall_time) << "; "
            << summary.end_reason << "; results in " << prm.output.directory
            << std::endl;
      print_results(summary);
      timer.print_summary();
      report_due = true;
    }

    template <int dim>
    void TimeLoop<dim>::print_results(const RunSummary &summary)
    {
      const auto &sh = sheet.summary();
      std::string zones;
      for (unsigned int z = material::n_safety_zones; z-- > 0;)
        if (sh.zone_count[z] > 0)
          zones += (zones.empty() ? " " : ", ") +
                   material::zone_name(material::SafetyZone(z)) + " " +
                   std::to_string(sh.zone_count[z]);
      pcout << "forming results: minimum thickness " << sh.min_thickness
            << " mm (thinning " << sh.max_thinning << " %), margin to the FLC "
            << sh.flc_margin << " %; FLD zones (columns):" << zones << "\n";
      pcout << (split.split()
                  ? "split: " +
                      what<dim>(split.split_measure(),
                                split.first(),
                                prm.material) +
                      " at punch travel " + mm(split.first().travel) + ", at " +
                      split.first().where(prm.geometry.model)
                  : std::string("no split"))
            << "\n";
      if (damage.criterion() != parameters::FractureCriterion::none)
        {
          const auto stroke = [](const double s) {
            return s >= 0 ? mm(s) : std::string("not reached");
          };
          pcout << "fracture criterion: "
                << (summary.critical_stroke >= 0
                      ? "reaches 1 at " + mm(summary.critical_stroke)
                      : std::string("below 1 up to the end of the run"))
                << " (through-thickness average: "
                << stroke(summary.through_thickness.stroke)
                << ", local maximum: " << stroke(summary.local.stroke) << ")\n";
        }
      for (const auto &w : run_warnings())
        pcout << "warning: " << w << "\n";
      pcout << std::flush;
    }

    template <int dim>
    void TimeLoop<dim>::close_after_error(RunSummary        &summary,
                                          const std::string &error)
    {
      std::ostringstream s;
      s << "error in step " << state.step + 1 << " (punch travel "
        << state.tools.punch_travel() << " mm): " << error;
      summary.end_reason = s.str();
      summary.wall_time  = seconds();
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      try
        {
          // The columns of the last converged step, if rank 0 holds them
          // all (one rank); on several ranks, sheet.csv of the last output
          // step stays (collective calls may hang now).
          if (Utilities::MPI::n_mpi_processes(comm) == 1)
            sheet.write_csv(MPI_COMM_SELF, prm.output.directory);
          Utilities::System::MemoryStats mem;
          Utilities::System::get_memory_stats(mem);
          summary.peak_memory_kb          = mem.VmHWM;
          summary.peak_memory_kb_max_rank = mem.VmHWM;
          write_summary(summary);
          report_due = true;
        }
      catch (const std::exception &e)
        {
          std::cerr << "formsolve: warning: the closing files after the "
                       "error are incomplete: "
                    << app::exception_text(e) << std::endl;
        }
    }

#define INSTANTIATE(dim)                                          \
  template RunSummary TimeLoop<dim>::run(const bool);             \
  template void       TimeLoop<dim>::run_steps(RunSummary &);     \
  template bool       TimeLoop<dim>::checkpoint_due() const;      \
  template double     TimeLoop<dim>::split_stop_travel() const;   \
  template void       TimeLoop<dim>::announce_split(              \
    const std::vector<SplitMeasure> &);                     \
  template std::string TimeLoop<dim>::split_reason() const;       \
  template std::string TimeLoop<dim>::failure_reason(             \
    const solver::StepReport &) const;                            \
  template void TimeLoop<dim>::finish(RunSummary &);              \
  template void TimeLoop<dim>::print_results(const RunSummary &); \
  template void TimeLoop<dim>::close_after_error(RunSummary &,    \
                                                 const std::string &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
