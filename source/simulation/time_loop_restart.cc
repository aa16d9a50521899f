// What the time loop keeps in a checkpoint besides the State (its running
// statistics, the step control's time step, the output records), the
// checkpoint itself, and the part a run starts with: a new blank or an
// earlier run's (Geometry/Start from).
#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/time_loop.h>
#include <formsolve/simulation/tool_placement.h>

#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    namespace
    {
      std::string records(const postprocess::VtuWriter<2>::Records &r)
      {
        std::ostringstream s;
        s.precision(17);
        for (const auto &[t, f] : r)
          s << t << '|' << f << ';';
        return s.str();
      }

      postprocess::VtuWriter<2>::Records records(const std::string &text)
      {
        postprocess::VtuWriter<2>::Records r;
        std::istringstream                 in(text);
        std::string                        item;
        while (std::getline(in, item, ';'))
          if (const auto bar = item.find('|'); bar != std::string::npos)
            r.emplace_back(std::stod(item.substr(0, bar)),
                           item.substr(bar + 1));
        return r;
      }
    } // namespace

    template <int dim>
    std::string TimeLoop<dim>::parameter_listing() const
    {
      std::ostringstream s;
      parameter_handler.print_parameters(s, ParameterHandler::PRM);
      return s.str();
    }

    template <int dim>
    Metadata TimeLoop<dim>::loop_metadata(const RunSummary &s) const
    {
      Metadata    m = split.save();
      std::string loaded;
      for (const bool l : tool_loaded)
        loaded += l ? '1' : '0';
      m["tools_loaded"] = loaded;
      m.merge(Metadata{
        {"summary.newton_iterations", std::to_string(s.newton_iterations)},
        {"summary.linear_iterations", std::to_string(s.linear_iterations)},
        {"summary.matrix_assemblies", std::to_string(s.matrix_assemblies)},
        {"summary.factorisations", std::to_string(s.factorisations)},
        {"summary.factorisation_memory_mb",
         exact_text(s.factorisation_memory_mb)},
        {"summary.factor_entries", exact_text(s.factor_entries)},
        {"summary.cutbacks", std::to_string(s.cutbacks)},
        {"summary.coarse_start_iterations",
         std::to_string(s.coarse_start_iterations)},
        {"summary.newton_wall_time", exact_text(s.newton_wall_time)},
        {"summary.wall_time", exact_text(s.wall_time)},
        {"summary.n_dofs", exact_text(s.n_dofs)},
        {"summary.dof_steps", exact_text(s.dof_steps)},
        {"summary.peak_punch_force", exact_text(s.peak_punch_force)},
        {"summary.peak_force_travel", exact_text(s.peak_force_travel)},
        {"summary.max_penetration", exact_text(s.max_penetration)},
        {"summary.ironing_travel", exact_text(s.ironing_travel)},
        {"summary.max_ironing_force", exact_text(s.max_ironing_force)},
        {"summary.max_ironing_pressure", exact_text(s.max_ironing_pressure)},
        {"summary.critical_stroke", exact_text(s.critical_stroke)},
        {"summary.fracture_location", s.fracture_location},
        {"summary.local.stroke", exact_text(s.local.stroke)},
        {"summary.local.location", s.local.location},
        {"summary.local.last", exact_text(s.local.last)},
        {"summary.local.last_travel", exact_text(s.local.last_travel)},
        {"summary.through.stroke", exact_text(s.through_thickness.stroke)},
        {"summary.through.location", s.through_thickness.location},
        {"summary.through.last", exact_text(s.through_thickness.last)},
        {"summary.through.last_travel",
         exact_text(s.through_thickness.last_travel)},
        {"time_step", exact_text(step_solver.time_step())},
        {"last_output_step", std::to_string(last_output_step)},
        {"refinement_rows",
         std::to_string(refinement_log ? refinement_log->n_rows() : 0)},
        {"pvd.solution", records(writer->solution_records())},
        {"pvd.revolved", records(writer->revolved_pvd_records())},
        {"pvd.tools", records(tool_writer->pvd_records())}});
      return m;
    }

    template <int dim>
    void TimeLoop<dim>::restore_loop(const Metadata &m, RunSummary &s)
    {
      s.newton_iterations = std::stoul(m.at("summary.newton_iterations"));
      s.linear_iterations = std::stoul(m.at("summary.linear_iterations"));
      // Absent in checkpoints written before it was counted: 0.
      auto optional = [&m](const std::string &key) {
        return m.count(key) ? std::stod(m.at(key)) : 0.;
      };
      s.matrix_assemblies       = optional("summary.matrix_assemblies");
      s.coarse_start_iterations = optional("summary.coarse_start_iterations");
      s.factorisations          = optional("summary.factorisations");
      s.factorisation_memory_mb = optional("summary.factorisation_memory_mb");
      s.factor_entries          = optional("summary.factor_entries");
      s.cutbacks                = std::stoul(m.at("summary.cutbacks"));
      s.newton_wall_time        = std::stod(m.at("summary.newton_wall_time"));
      s.wall_before             = std::stod(m.at("summary.wall_time"));
      s.n_dofs                  = std::stod(m.at("summary.n_dofs"));
      s.dof_steps               = std::stod(m.at("summary.dof_steps"));
      s.peak_punch_force        = std::stod(m.at("summary.peak_punch_force"));
      s.peak_force_travel       = std::stod(m.at("summary.peak_force_travel"));
      s.max_penetration         = std::stod(m.at("summary.max_penetration"));
      s.ironing_travel          = m.count("summary.ironing_travel")
                                    ? optional("summary.ironing_travel")
                                    : -1.;
      s.max_ironing_force       = optional("summary.max_ironing_force");
      s.max_ironing_pressure    = optional("summary.max_ironing_pressure");
      s.critical_stroke         = std::stod(m.at("summary.critical_stroke"));
      s.fracture_location       = m.at("summary.fracture_location");
      for (auto &[w, name] :
           {std::pair<RunSummary::Watch *, std::string>{&s.local, "local"},
            {&s.through_thickness, "through"}})
        {
          const std::string k = "summary." + name + ".";
          w->stroke           = std::stod(m.at(k + "stroke"));
          w->location         = m.at(k + "location");
          w->last             = std::stod(m.at(k + "last"));
          w->last_travel      = std::stod(m.at(k + "last_travel"));
        }
      s.steps = state.step;
      step_solver.set_time_step(std::stod(m.at("time_step")));
      last_output_step = std::stoi(m.at("last_output_step"));
      refinement_rows  = std::stoul(m.at("refinement_rows"));
      writer->set_records(records(m.at("pvd.solution")),
                          records(m.at("pvd.revolved")));
      // Absent in checkpoints written before the tools were output.
      if (m.count("pvd.tools"))
        tool_writer->set_records(records(m.at("pvd.tools")));
      split.load(m);
      tool_loaded.clear();
      if (m.count("tools_loaded"))
        for (const char c : m.at("tools_loaded"))
          tool_loaded.push_back(c == '1');
    }

    template <int dim>
    void TimeLoop<dim>::make_part()
    {
      if (prm.geometry.start_from.empty())
        state.create_mesh();
      else
        {
          earlier = std::make_unique<EarlierRun>(
            find_earlier_run(prm.geometry.start_from,
                             prm.output.directory,
                             parameter_listing()));
          load_earlier_part(*earlier, state, history_update);
          if (earlier->trimmed)
            criteria.start_at_level(earlier->part_mesh.level);
        }
      for (const auto &line : place_tools_against_part(state))
        pcout << line << std::endl;
    }

    template <int dim>
    void TimeLoop<dim>::save_checkpoint(RunSummary &summary, const bool end)
    {
      TimerOutput::Scope t(timer, "checkpoint");
      step_solver.release_factors();
      summary.wall_time    = seconds();
      auto meta            = loop_metadata(summary);
      meta["punch_travel"] = exact_text(state.tools.punch_travel());
      // A next operation starts only from a finished part; a trimmed one
      // carries which cells it kept.
      meta["finished"] = end && !summary.solver_failed ? "1" : "0";
      checkpoint->save(state,
                       meta,
                       end ? sprung_shape.get() : nullptr,
                       end ? kept.get() : nullptr);
      last_checkpoint = seconds();
    }

    // The class is instantiated in time_loop.cc; these members are here.
#define INSTANTIATE(dim)                                                       \
  template std::string TimeLoop<dim>::parameter_listing() const;               \
  template Metadata    TimeLoop<dim>::loop_metadata(const RunSummary &) const; \
  template void TimeLoop<dim>::restore_loop(const Metadata &, RunSummary &);   \
  template void TimeLoop<dim>::make_part();                                    \
  template void TimeLoop<dim>::save_checkpoint(RunSummary &, const bool);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
