#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/history_writer.h>
#include <formsolve/state/sheet_integrals.h>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /// Suffixes of the draw-in directions.
      template <int dim>
      std::vector<std::string> directions()
      {
        return dim == 2 ? std::vector<std::string>{""}
                        : std::vector<std::string>{"_x", "_diagonal", "_y"};
      }

      /// columns_<zone> of the forming limit diagram's zones.
      std::vector<std::string> zone_columns()
      {
        std::vector<std::string> c;
        for (unsigned int z = 0; z < material::n_safety_zones; ++z)
          c.push_back("columns_" +
                      material::zone_key(static_cast<material::SafetyZone>(z)));
        return c;
      }

      /// history.csv: the process as the forming engineer reads it.
      template <int dim>
      std::vector<std::string> columns(const tools::ToolSet<dim>   &tools,
                                       const parameters::DrawBeads &beads,
                                       const model::Model           m)
      {
        std::vector<std::string> c = {"step",
                                      "time",
                                      "punch_travel",
                                      "punch_force",
                                      "force_travel"};
        for (unsigned int t = 0; t < tools.size(); ++t)
          c.push_back("force_" + tools.key(t));
        c.insert(c.end(), {"ironing_force", "ironing_pressure"});
        if (tools.holder_index() != tools::ToolSet<dim>::none)
          c.insert(c.end(), {"holder_displacement", "holder_engaged"});
        // Additional tools: where each is along its direction, and the force
        // it exerts on the sheet along it (the set force under control).
        for (unsigned int t = tools.first_additional(); t < tools.size(); ++t)
          c.insert(c.end(),
                   {"position_" + tools.key(t),
                    "force_along_" + tools.key(t),
                    "force_x_" + tools.key(t)});
        // Draw beads: restraining and opening force, restraining work, and
        // the material drawn across (section 6d of doc/theory.md).
        for (const auto &b : beads.beads)
          for (const char *what : {"_force", "_opening", "_work", "_drawn"})
            c.push_back(b.key() + what);
        c.push_back("max_equivalent_strain");
        const auto where = model::coordinate_names(m);
        c.insert(c.end(),
                 {"min_thickness",
                  "min_thickness_R0",
                  "max_thinning_percent",
                  "max_thickening_percent",
                  "cup_height",
                  "flc_margin_percent"});
        for (const auto &x : where)
          c.push_back("min_thickness_" + x);
        for (const auto &d : directions<dim>())
          c.insert(c.end(), {"rim_radius" + d, "draw_in" + d});
        c.push_back("max_oyane");
        for (const auto &x : where)
          c.push_back("max_oyane_" + x);
        c.insert(c.end(),
                 {"max_cockcroft_latham", "max_cockcroft_latham_integral"});
        for (const auto &x : where)
          c.push_back("max_cockcroft_latham_" + x);
        // Column averages through the thickness (section 11a).
        c.push_back("max_oyane_through_thickness");
        for (const auto &x : where)
          c.push_back("max_oyane_through_thickness_" + x);
        c.push_back("max_cockcroft_latham_through_thickness");
        for (const auto &x : where)
          c.push_back("max_cockcroft_latham_through_thickness_" + x);
        for (const auto &z : zone_columns())
          c.push_back(z);
        return c;
      }

      /// solver.csv: how the step was solved, and the checks of the solution
      /// (penetration, volume).
      template <int dim>
      std::vector<std::string> solver_columns(const tools::ToolSet<dim> &tools)
      {
        std::vector<std::string> c = {"step",
                                      "time",
                                      "punch_travel",
                                      "time_step",
                                      "cutbacks",
                                      "max_penetration",
                                      "mean_penetration",
                                      "force_imbalance_z"};
        for (unsigned int t = 0; t < tools.size(); ++t)
          c.push_back("max_penetration_" + tools.key(t));
        c.insert(c.end(),
                 {"active_contacts",
                  "pairs_over_allowed",
                  "locked_pairs",
                  "min_penalty",
                  "max_penalty",
                  "newton_iterations",
                  "linear_iterations",
                  "picard_iterations",
                  "strict_passes",
                  "max_linear_iterations",
                  "condition_estimate",
                  "dofs",
                  "volume",
                  "wall_time"});
        return c;
      }
    } // namespace

    template <int dim>
    HistoryWriter<dim>::HistoryWriter(const state::State<dim> &state,
                                      const int                keep_rows)
        : table(state.prm.output.directory + "/history.csv",
                columns(state.tools,
                        state.prm.tools.draw_beads,
                        state.prm.geometry.model),
                Utilities::MPI::this_mpi_process(state.comm) == 0,
                keep_rows)
        , solver_table(state.prm.output.directory + "/solver.csv",
                       solver_columns(state.tools),
                       Utilities::MPI::this_mpi_process(state.comm) == 0,
                       keep_rows)
    {}

    template <int dim>
    void HistoryWriter<dim>::write(const state::State<dim>  &state,
                                   const solver::StepReport &report,
                                   const contact::ContactStatistics<dim> &stats,
                                   const FormingMeasures<dim> &forming,
                                   const double                wall_time)
    {
      for (auto *t : {&table, &solver_table})
        {
          t->set("step", state.step);
          t->set("time", state.time);
          t->set("punch_travel", state.tools.punch_travel());
        }
      set_tool_columns(state, stats);
      set_solver_columns(state, report, stats);
      set_forming_columns(state, forming);
      solver_table.set("wall_time",
                       state.prm.output.wall_time_in_history ? wall_time : 0.);
      table.write_row();
      solver_table.write_row();
    }

    template <int dim>
    void HistoryWriter<dim>::set_tool_columns(
      const state::State<dim>               &state,
      const contact::ContactStatistics<dim> &stats)
    {
      const auto        &tools = state.tools;
      const double       sym   = state.prm.geometry.symmetry_factor();
      const unsigned int z     = dim - 1;
      // Axial (z) forces of the sheet on the tools, full part, pressing = +.
      table.set("punch_force", sym * stats.tool_force[tools.punch_index()][z]);
      table.set("force_travel", stats.force_travel);
      for (unsigned int t = 0; t < tools.size(); ++t)
        table.set("force_" + tools.key(t),
                  sym * std::abs(stats.tool_force[t][z]));
      table.set("ironing_force",
                sym * contact::ironing_force(stats,
                                             tools.punch_index(),
                                             tools.die_index()));
      table.set("ironing_pressure",
                contact::ironing_pressure(stats,
                                          tools.punch_index(),
                                          tools.die_index()));
      if (tools.holder_index() != tools::ToolSet<dim>::none)
        {
          table.set("holder_displacement",
                    tools[tools.holder_index()].displacement()[z]);
          const auto *control = state.force_control(tools.holder_index());
          table.set("holder_engaged", control && control->active ? 1 : 0);
        }
      for (unsigned int t = tools.first_additional(); t < tools.size(); ++t)
        {
          const Tensor<1, dim> &d = tools.motion(t).direction;
          table.set("position_" + tools.key(t), tools[t].displacement() * d);
          table.set("force_along_" + tools.key(t),
                    -sym * (stats.tool_force[t] * d));
          // Across the part: the modelled part's own (a mirrored half pulls
          // the other way), what the sheet exerts on the tool.
          table.set("force_x_" + tools.key(t), stats.tool_force[t][0]);
        }
      const auto &beads = state.prm.tools.draw_beads.beads;
      for (unsigned int b = 0; b < beads.size(); ++b)
        {
          const auto &r = state.beads[b];
          table.set(beads[b].key() + "_force", sym * r.force);
          table.set(beads[b].key() + "_opening", sym * r.opening);
          table.set(beads[b].key() + "_work", sym * r.work);
          table.set(beads[b].key() + "_drawn", r.drawn);
        }
    }

    template <int dim>
    void HistoryWriter<dim>::set_solver_columns(
      const state::State<dim>               &state,
      const solver::StepReport              &report,
      const contact::ContactStatistics<dim> &stats)
    {
      const auto        &tools = state.tools;
      const unsigned int z     = dim - 1;
      solver_table.set("time_step", report.dt);
      solver_table.set("cutbacks", report.cutbacks);
      // The sheet's equilibrium along z, where nothing but the tools holds
      // it: the tools' z forces sum to zero within Newton's tolerance. As a
      // fraction of their magnitudes, so that round-off stays below 1e-10.
      double sum_z = 0, magnitude_z = 0;
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          sum_z += stats.tool_force[t][z];
          magnitude_z += std::abs(stats.tool_force[t][z]);
        }
      solver_table.set("force_imbalance_z",
                       magnitude_z > 0 ? sum_z / magnitude_z : 0.);
      solver_table.set("max_penetration", stats.max_penetration);
      solver_table.set("mean_penetration", stats.mean_penetration);
      for (unsigned int t = 0; t < tools.size(); ++t)
        solver_table.set("max_penetration_" + tools.key(t),
                         stats.tool_max_penetration[t]);
      solver_table.set("active_contacts", stats.n_active);
      solver_table.set("pairs_over_allowed", stats.n_over_allowed);
      solver_table.set("locked_pairs", stats.n_locked);
      solver_table.set("min_penalty", stats.min_factor);
      solver_table.set("max_penalty", stats.max_factor);
      solver_table.set("newton_iterations", report.iterations);
      solver_table.set("linear_iterations", report.linear_iterations);
      solver_table.set("picard_iterations", report.picard_iterations);
      solver_table.set("strict_passes", report.passes);
      solver_table.set("max_linear_iterations", report.max_linear_iterations);
      solver_table.set("condition_estimate", report.condition_estimate);
      solver_table.set("dofs", state.dof_handler.n_dofs());
      solver_table.set("volume",
                       state.prm.geometry.symmetry_factor() * volume(state));
    }

    template <int dim>
    void
    HistoryWriter<dim>::set_forming_columns(const state::State<dim>    &state,
                                            const FormingMeasures<dim> &forming)
    {
      table.set("max_equivalent_strain",
                maximum(state, &state::QuadraturePointHistory::strain).value);
      const auto &sheet = forming.sheet;
      const auto  where = model::coordinate_names(state.prm.geometry.model);
      table.set("min_thickness", sheet.min_thickness);
      table.set("min_thickness_R0", sheet.min_thickness_radius);
      table.set("max_thinning_percent", sheet.max_thinning);
      table.set("max_thickening_percent", sheet.max_thickening);
      table.set("cup_height", sheet.cup_height);
      table.set("flc_margin_percent", sheet.flc_margin);
      for (unsigned int d = 0; d < dim; ++d)
        {
          table.set("min_thickness_" + where[d],
                    sheet.min_thickness_location[d]);
          table.set("max_oyane_" + where[d], forming.oyane.location[d]);
          table.set("max_cockcroft_latham_" + where[d],
                    forming.cockcroft_latham.location[d]);
          const auto &c = forming.through_thickness;
          table.set("max_oyane_through_thickness_" + where[d],
                    c.oyane.location[d]);
          table.set("max_cockcroft_latham_through_thickness_" + where[d],
                    c.cockcroft_latham.location[d]);
        }
      const auto dirs = directions<dim>();
      for (unsigned int i = 0; i < dirs.size(); ++i)
        {
          table.set("rim_radius" + dirs[i], sheet.rim_radius[i]);
          table.set("draw_in" + dirs[i], sheet.draw_in[i]);
        }
      table.set("max_oyane", forming.oyane.value);
      table.set("max_cockcroft_latham", forming.cockcroft_latham_ratio);
      table.set("max_cockcroft_latham_integral",
                forming.cockcroft_latham.value);
      table.set("max_oyane_through_thickness",
                forming.through_thickness.oyane.value);
      table.set("max_cockcroft_latham_through_thickness",
                forming.through_thickness.cockcroft_latham.value);
      const auto zones = zone_columns();
      for (unsigned int z = 0; z < zones.size(); ++z)
        table.set(zones[z], sheet.zone_count[z]);
    }

#define INSTANTIATE(dim) template class HistoryWriter<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
