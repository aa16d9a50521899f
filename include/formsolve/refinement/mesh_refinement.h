// Where the mesh is refined: bands around the tools' profile radii (where the
// sheet bends) and, optionally, a Kelly indicator on the velocity.
#pragma once

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/parameters/parameters.h>
#include <formsolve/state/quadrature_history.h>
#include <formsolve/tools/tool_set.h>

#include <vector>

namespace formsolve
{
  namespace refinement
  {
    /// Cells flagged by one call of RefinementCriteria::mark (all ranks).
    struct RefinementFlags
    {
      unsigned int refine  = 0;
      unsigned int coarsen = 0;
    };

    template <int dim>
    class RefinementCriteria
    {
    public:
      /// @p initial_level: the triangulation level of the initial mesh.
      RefinementCriteria(const parameters::MeshRefinement &p,
                         const tools::ToolSet<dim>        &tools,
                         unsigned int                      initial_level);

      /// A trimmed part's own mesh starts at the earlier mesh's level
      /// @p part_level: levels then count from the initial mesh's level
      /// minus it (negative if the part's coarse cells are finer).
      void start_at_level(const unsigned int part_level)
      {
        initial_level -= static_cast<int>(part_level);
      }

      /// Sets refinement and coarsening flags on the locally owned cells of
      /// @p dof_handler's triangulation, positions from @p mapping (current
      /// configuration). Collective.
      RefinementFlags
      mark(const dealii::DoFHandler<dim>               &dof_handler,
           const dealii::Mapping<dim>                  &mapping,
           const dealii::TrilinosWrappers::MPI::Vector &velocity,
           const tools::ToolSet<dim>                   &tools) const;

      /// Level wanted by the radius bands at @p x (current position) for a
      /// cell of size @p diameter, with the band scaled by @p band_factor.
      unsigned int band_level(const dealii::Point<dim>  &x,
                              const double               diameter,
                              const tools::ToolSet<dim> &tools,
                              const double               band_factor) const;

    private:
      /// Clears the coarsening flags of every family whose coarse cell would
      /// move one of the family's vertices (current configuration) by more
      /// than the shape tolerance. Returns how many flags it cleared.
      unsigned int keep_shape(const dealii::DoFHandler<dim> &dof_handler,
                              const dealii::Mapping<dim>    &mapping) const;

      parameters::MeshRefinement prm;
      int                        initial_level;
      std::vector<unsigned int>  tool_level; // per tool of the ToolSet
    };
  } // namespace refinement
} // namespace formsolve
