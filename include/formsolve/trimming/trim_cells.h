// Trimming the formed part (doc/trimming.md; doc/theory.md, section 13):
// the cells the trim line crosses are refined until their nodes lie within
// Trimming/Tolerance of it, and the part keeps the cells whose centres lie
// on its side, with everything their points hold (thickness, plastic
// strain, damage, stresses). The cells cut away stay in the mesh, marked.
#pragma once

#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>
#include <formsolve/trimming/trim_shape.h>

#include <vector>

namespace formsolve
{
  namespace trimming
  {

    /// What the trim did (all ranks).
    struct TrimReport
    {
      unsigned int passes = 0; // refinement passes along the line
      /// Largest distance from the trim line of a node of a cell it
      /// crosses, after refinement (mm): the cut edge lies within it.
      double edge_deviation = 0;
      double cells_before = 0, cells_after = 0, cells_kept = 0;
      double volume_before = 0, volume_kept = 0; // mm^3, the model
      double strain_kept = 0; // int eps dV over the kept cells
    };

    /// Kept (true) or cut away, by active cell index (locally owned and
    /// ghost cells).
    using KeptCells = std::vector<bool>;

    /// Refines @p state along @p shape's line by Trimming/Tolerance and
    /// Maximum refinement, carrying the state over, so that no cut-away
    /// cell next to a kept one is coarser than it; returns the kept cells
    /// in @p kept. Collective.
    template <int dim>
    TrimReport trim_part(state::State<dim>               &state,
                         const TrimShape<dim>            &shape,
                         const parameters::Trimming      &trimming,
                         const state::HistoryUpdate<dim> &update,
                         KeptCells                       &kept);

    /// The cells of @p state whose centres @p shape keeps.
    template <int dim>
    KeptCells kept_cells(const state::State<dim> &state,
                         const TrimShape<dim>    &shape);

    /// Before any work: the trim curve of Trimming/Curve file must cross
    /// the blank (some of its cells on either side); throws naming the
    /// entry and file. The files are read (errors name them). Collective.
    template <int dim>
    void check_trim_curve(const state::State<dim>    &state,
                          const parameters::Trimming &trimming);

    /// The centres of the faces between kept and cut-away cells (current
    /// configuration, locally owned cells), in no order.
    template <int dim>
    std::vector<dealii::Point<dim>> cut_faces(const state::State<dim> &state,
                                              const KeptCells         &kept);
  } // namespace trimming
} // namespace formsolve
