// A trimmed part's own mesh for a next operation (doc/next-operation.md;
// doc/theory.md, section 13). The earlier run's mesh keeps its cut-away
// cells, marked, and a hexahedral forest cannot lose cells below its coarse
// level; so the part is meshed anew in the reference configuration: the
// earlier mesh's coarsest complete level without the cells mostly cut
// away, the nodes next to the cut moved onto the cut surface, and then
// refined where the earlier mesh was finer (part_transfer.h).
#pragma once

#include <deal.II/distributed/tria.h>

#include <formsolve/state/state.h>
#include <formsolve/trimming/trim_cells.h>

namespace formsolve
{
  namespace trimming
  {
    /// How the part's mesh came out (all ranks).
    struct PartMesh
    {
      /// The earlier mesh's level the part's coarse cells are, and its
      /// cells at that level kept and left out.
      unsigned int level        = 0;
      unsigned int kept         = 0;
      unsigned int left_out     = 0;
      double       largest_move = 0; // mm, of a node moved onto the cut
      /// Smallest ratio of a cell's smallest to largest corner Jacobian
      /// (1 for a parallelepiped) among the cells with a moved node.
      double worst_corner_ratio = 1;
    };

    /// Fills @p tria (empty) with the coarse mesh of the part that
    /// @p earlier (the earlier run's state, reference configuration in its
    /// mesh) kept by @p kept (by active cell index, locally owned cells).
    /// Throws naming Geometry/Start from if a moved node inverts a cell.
    /// Collective.
    template <int dim>
    PartMesh
    create_part_mesh(const state::State<dim>                           &earlier,
                     const KeptCells                                   &kept,
                     dealii::parallel::distributed::Triangulation<dim> &tria);
  } // namespace trimming
} // namespace formsolve
