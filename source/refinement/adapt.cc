#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/adapt.h>
#include <formsolve/refinement/history_transfer.h>

namespace formsolve
{
  namespace refinement
  {
    using namespace dealii;
    using simulation::VectorType;

    template <int dim>
    AdaptReport adapt_mesh(simulation::State<dim>        &state,
                           const RefinementCriteria<dim> &criteria,
                           const solver::Assembler<dim>  &assembler,
                           const std::function<void()>   &before_change)
    {
      state.velocity_ghost = state.velocity;
      const auto flags     = criteria.mark(state.dof_handler,
                                       *state.mapping,
                                       state.velocity_ghost,
                                       state.tools);
      if (flags.refine + flags.coarsen == 0)
        return AdaptReport();
      AdaptReport report = adapt_flagged(state, assembler, before_change);
      report.refine      = flags.refine;
      report.coarsen     = flags.coarsen;
      return report;
    }

    template <int dim>
    AdaptReport adapt_flagged(simulation::State<dim>       &state,
                              const solver::Assembler<dim> &assembler,
                              const std::function<void()>  &before_change)
    {
      AdaptReport report;
      auto       &tria = state.tria;
      // Smoothing drops coarsening flags of incomplete families (and adds
      // refinement for the 2:1 balance): count what is left.
      tria.prepare_coarsening_and_refinement();
      unsigned int left = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (cell->refine_flag_set() || cell->coarsen_flag_set()))
          ++left;
      if (Utilities::MPI::sum(left, state.comm) == 0)
        return report;
      if (before_change)
        before_change();

      report.volume_before =
        assembler.volume(state.dof_handler, *state.mapping);
      report.strain_before = assembler.strain_integral(state.dof_handler,
                                                       *state.mapping,
                                                       state.history);
      report.damage_before =
        assembler.history_integral(state.dof_handler,
                                   *state.mapping,
                                   state.history,
                                   &simulation::QuadraturePointHistory::oyane);
      report.cells_before = tria.n_global_active_cells();

      // Velocity, displacement and the contact state, as nodal fields:
      // nodes that persist keep their values, new nodes interpolate them.
      parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
        state.dof_handler);
      const std::vector<VectorType>   fields = state.transferable_fields();
      std::vector<const VectorType *> in;
      for (const auto &f : fields)
        in.push_back(&f);
      transfer.prepare_for_coarsening_and_refinement(in);
      assembler.exchange_volume_offsets(state.dof_handler,
                                        *state.mapping,
                                        state.history);
      // History: copied from the nearest old point, which makes no new
      // extreme, with the integral over each family kept.
      HistoryTransfer<dim> history_transfer(assembler.quadrature(),
                                            state.reference_mapping,
                                            state.kinematics);
      history_transfer.prepare(tria, state.history);
      state.mapping.reset();
      tria.execute_coarsening_and_refinement();

      state.setup_dofs(assembler);
      std::vector<VectorType>   transferred(fields.size(),
                                          VectorType(state.owned, state.comm));
      std::vector<VectorType *> out;
      for (auto &f : transferred)
        out.push_back(&f);
      transfer.interpolate(out);
      history_transfer.interpolate(state.history);
      state.set_transferable_fields(transferred);
      assembler.exchange_volume_offsets(state.dof_handler,
                                        *state.mapping,
                                        state.history);
      state.update_contact_areas();

      report.changed      = true;
      report.cells_after  = tria.n_global_active_cells();
      report.dofs         = state.dof_handler.n_dofs();
      report.volume_after = assembler.volume(state.dof_handler, *state.mapping);
      report.strain_after = assembler.strain_integral(state.dof_handler,
                                                      *state.mapping,
                                                      state.history);
      report.damage_after =
        assembler.history_integral(state.dof_handler,
                                   *state.mapping,
                                   state.history,
                                   &simulation::QuadraturePointHistory::oyane);
      return report;
    }

#define INSTANTIATE(dim)                                             \
  template AdaptReport adapt_mesh(simulation::State<dim> &,          \
                                  const RefinementCriteria<dim> &,   \
                                  const solver::Assembler<dim> &,    \
                                  const std::function<void()> &);    \
  template AdaptReport adapt_flagged(simulation::State<dim> &,       \
                                     const solver::Assembler<dim> &, \
                                     const std::function<void()> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace refinement
} // namespace formsolve
