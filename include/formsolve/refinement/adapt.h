// Adapts the mesh of a State by the refinement criteria and carries the
// whole state over: velocity, displacement, quadrature history, contact
// nodes and areas.
#pragma once

#include <formsolve/refinement/mesh_refinement.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>

#include <functional>

namespace formsolve
{
  namespace refinement
  {
    /// One adaptation, for refinement.csv.
    struct AdaptReport
    {
      bool         changed      = false;
      double       cells_before = 0, cells_after = 0, dofs = 0;
      unsigned int refine = 0, coarsen = 0; // cells flagged by the criteria
      double       volume_before = 0, volume_after = 0;
      double       strain_before = 0, strain_after = 0; // int eps dV
      double       damage_before = 0, damage_after = 0; // int I dV (Oyane)
    };

    /// Refine and coarsen @p state's mesh by @p criteria, carrying the
    /// state over, contact state included (doc/theory.md, section 7a).
    /// @p before_change runs once it is known that the mesh changes, before
    /// the transfer (the caller frees what the new mesh makes useless, e.g.
    /// the factors, whose memory the transfer may need); not otherwise.
    template <int dim>
    AdaptReport adapt_mesh(state::State<dim>               &state,
                           const RefinementCriteria<dim>   &criteria,
                           const state::HistoryUpdate<dim> &update,
                           const std::function<void()>     &before_change = {});

    /// The same for the refinement and coarsening flags already set on
    /// @p state's triangulation (locally owned cells), whoever set them.
    /// Without @p measure the report's volume and integrals stay 0 (each
    /// is a pass over the mesh).
    template <int dim>
    AdaptReport adapt_flagged(state::State<dim>               &state,
                              const state::HistoryUpdate<dim> &update,
                              const std::function<void()> &before_change = {},
                              const bool                   measure = true);
  } // namespace refinement
} // namespace formsolve
