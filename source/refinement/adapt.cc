#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/adapt.h>
#include <formsolve/refinement/history_transfer.h>
#include <formsolve/state/sheet_integrals.h>

namespace formsolve
{
  namespace refinement
  {
    using namespace dealii;
    using History = state::QuadraturePointHistory;
    using state::VectorType;

    template <int dim>
    AdaptReport adapt_mesh(state::State<dim>               &state,
                           const RefinementCriteria<dim>   &criteria,
                           const state::HistoryUpdate<dim> &update,
                           const std::function<void()>     &before_change)
    {
      state.velocity_ghost = state.velocity;
      const auto flags     = criteria.mark(state.dof_handler,
                                       *state.mapping,
                                       state.velocity_ghost,
                                       state.tools);
      if (flags.refine + flags.coarsen == 0)
        return AdaptReport();
      AdaptReport report = adapt_flagged(state, update, before_change);
      report.refine      = flags.refine;
      report.coarsen     = flags.coarsen;
      return report;
    }

    template <int dim>
    AdaptReport adapt_flagged(state::State<dim>               &state,
                              const state::HistoryUpdate<dim> &update,
                              const std::function<void()>     &before_change,
                              const bool                       measure)
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

      if (measure)
        {
          report.volume_before = volume(state);
          report.strain_before = integral(state, &History::strain);
          report.damage_before = integral(state, &History::oyane);
        }
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
      update.exchange_volume_offsets(state.dof_handler,
                                     *state.mapping,
                                     state.history);
      // History: copied from the nearest old point, which makes no new
      // extreme, with the integral over each family kept.
      HistoryTransfer<dim> history_transfer(state.history_rule,
                                            state.reference_mapping,
                                            state.kinematics);
      history_transfer.prepare(tria, state.history);
      state.mapping.reset();
      tria.execute_coarsening_and_refinement();

      state.setup_dofs();
      std::vector<VectorType>   transferred(fields.size(),
                                          VectorType(state.owned, state.comm));
      std::vector<VectorType *> out;
      for (auto &f : transferred)
        out.push_back(&f);
      transfer.interpolate(out);
      history_transfer.interpolate(state.history);
      state.set_transferable_fields(transferred);
      update.exchange_volume_offsets(state.dof_handler,
                                     *state.mapping,
                                     state.history);
      state.update_contact_areas();

      report.changed     = true;
      report.cells_after = tria.n_global_active_cells();
      report.dofs        = state.dof_handler.n_dofs();
      if (measure)
        {
          report.volume_after = volume(state);
          report.strain_after = integral(state, &History::strain);
          report.damage_after = integral(state, &History::oyane);
        }
      return report;
    }

#define INSTANTIATE(dim)                                                \
  template AdaptReport adapt_mesh(state::State<dim> &,                  \
                                  const RefinementCriteria<dim> &,      \
                                  const state::HistoryUpdate<dim> &,    \
                                  const std::function<void()> &);       \
  template AdaptReport adapt_flagged(state::State<dim> &,               \
                                     const state::HistoryUpdate<dim> &, \
                                     const std::function<void()> &,     \
                                     const bool);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace refinement
} // namespace formsolve
