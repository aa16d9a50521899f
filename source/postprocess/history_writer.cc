#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/history_writer.h>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      std::vector<std::string> columns(const tools::ToolSet<dim> &tools)
      {
        std::vector<std::string> c = {"step",
                                      "time",
                                      "time_step",
                                      "cutbacks",
                                      "punch_travel",
                                      "punch_force"};
        for (unsigned int t = 0; t < tools.size(); ++t)
          c.push_back("force_" + tools.key(t));
        if (tools.holder_index() != tools::ToolSet<dim>::none)
          c.insert(c.end(), {"holder_displacement", "holder_engaged"});
        c.insert(c.end(), {"max_penetration", "mean_penetration"});
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
                  "max_equivalent_strain",
                  "wall_time"});
        return c;
      }
    } // namespace

    template <int dim>
    HistoryWriter<dim>::HistoryWriter(const simulation::State<dim> &state)
        : table(state.prm.output.directory + "/history.csv",
                columns(state.tools),
                Utilities::MPI::this_mpi_process(state.comm) == 0)
    {}

    template <int dim>
    void HistoryWriter<dim>::write(const simulation::State<dim> &state,
                                   const solver::StepReport     &report,
                                   const contact::ContactStatistics<dim> &stats,
                                   const solver::Assembler<dim> &assembler,
                                   const double                  wall_time)
    {
      const auto        &tools = state.tools;
      const double       sym   = state.prm.geometry.symmetry_factor();
      const unsigned int z     = dim - 1;
      table.set("step", state.step);
      table.set("time", state.time);
      table.set("time_step", report.dt);
      table.set("cutbacks", report.cutbacks);
      table.set("punch_travel", tools.punch_travel());
      // Axial (z) forces of the sheet on the tools, full part, pressing = +.
      table.set("punch_force", sym * stats.tool_force[tools.punch_index()][z]);
      for (unsigned int t = 0; t < tools.size(); ++t)
        table.set("force_" + tools.key(t),
                  sym * std::abs(stats.tool_force[t][z]));
      if (tools.holder_index() != tools::ToolSet<dim>::none)
        {
          table.set("holder_displacement",
                    tools[tools.holder_index()].displacement()[z]);
          table.set("holder_engaged", state.holder.force_control ? 1 : 0);
        }
      table.set("max_penetration", stats.max_penetration);
      table.set("mean_penetration", stats.mean_penetration);
      for (unsigned int t = 0; t < tools.size(); ++t)
        table.set("max_penetration_" + tools.key(t),
                  stats.tool_max_penetration[t]);
      table.set("active_contacts", stats.n_active);
      table.set("pairs_over_allowed", stats.n_over_allowed);
      table.set("locked_pairs", stats.n_locked);
      table.set("min_penalty", stats.min_factor);
      table.set("max_penalty", stats.max_factor);
      table.set("newton_iterations", report.iterations);
      table.set("linear_iterations", report.linear_iterations);
      table.set("picard_iterations", report.picard_iterations);
      table.set("strict_passes", report.passes);
      table.set("max_linear_iterations", report.max_linear_iterations);
      table.set("condition_estimate", report.condition_estimate);
      table.set("dofs", state.dof_handler.n_dofs());
      table.set("volume",
                sym * assembler.volume(state.dof_handler, *state.mapping));
      table.set("max_equivalent_strain",
                assembler.max_strain(state.dof_handler, state.history));
      table.set("wall_time",
                state.prm.output.wall_time_in_history ? wall_time : 0.);
      table.write_row();
    }

#define INSTANTIATE(dim) template class HistoryWriter<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
