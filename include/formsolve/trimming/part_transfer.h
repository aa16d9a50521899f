// A trimmed part onto its own mesh (part_mesh.h): the mesh refined where
// the earlier one was finer, the shape and the history of the earlier run
// evaluated at the new nodes and material points (reference configuration),
// the history from the nearest earlier material point as in refinement.
#pragma once

#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>

namespace formsolve
{
  namespace trimming
  {
    /// Refines @p part (its coarse cells being the earlier mesh's level
    /// @p level) until no cell is coarser than the earlier cell at its
    /// centre, then sets up its DoFs. Collective.
    template <int dim>
    void refine_like(const state::State<dim> &earlier,
                     const unsigned int       level,
                     state::State<dim>       &part);

    /// The part at rest in the shape of @p shape (a displacement on the
    /// earlier mesh: as formed or sprung), with the earlier history; the
    /// volume offsets (doc/theory.md, eq. 5a) carried as in refinement,
    /// from the shape @p formed (the end of forming, where @p earlier's
    /// mapping is). Throws if a point of the part lies outside the earlier
    /// mesh. Collective.
    template <int dim>
    void transfer_part(state::State<dim>               &earlier,
                       const state::VectorType         &formed,
                       const state::VectorType         &shape,
                       const state::HistoryUpdate<dim> &update,
                       state::State<dim>               &part);
  } // namespace trimming
} // namespace formsolve
