#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/mesh_refinement.h>

#include <algorithm>
#include <array>
#include <set>

namespace formsolve
{
  namespace refinement
  {
    using namespace dealii;

    template <int dim>
    RefinementCriteria<dim>::RefinementCriteria(
      const parameters::MeshRefinement &p,
      const tools::ToolSet<dim>        &tools,
      const unsigned int                initial_level)
        : prm(p)
        , initial_level(initial_level)
    {
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          tool_level.push_back(t == tools.punch_index() ? p.punch_level
                               : t == tools.die_index() ? p.die_level
                               : t == tools.holder_index()
                                 ? p.holder_level
                                 : tools.refinement_level(t));
        }
    }

    template <int dim>
    unsigned int
    RefinementCriteria<dim>::band_level(const Point<dim>          &x,
                                        const double               diameter,
                                        const tools::ToolSet<dim> &tools,
                                        const double band_factor) const
    {
      unsigned int level = 0;
      for (unsigned int t = 0; t < tools.size(); ++t)
        if (tool_level[t] > level &&
            tools[t].distance_to_radius(x) - 0.5 * diameter <
              band_factor * prm.band_width)
          level = tool_level[t];
      return level;
    }

    template <int dim>
    RefinementFlags RefinementCriteria<dim>::mark(
      const DoFHandler<dim>                       &dof_handler,
      const Mapping<dim>                          &mapping,
      const dealii::TrilinosWrappers::MPI::Vector &velocity,
      const tools::ToolSet<dim>                   &tools) const
    {
      auto &tria = const_cast<parallel::distributed::Triangulation<dim> &>(
        dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
          dof_handler.get_triangulation()));
      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->clear_refine_flag();
          cell->clear_coarsen_flag();
        }

      const bool kelly = prm.indicator == parameters::Indicator::kelly;
      if (kelly)
        {
          Vector<float> indicator(tria.n_active_cells());
          KellyErrorEstimator<dim>::estimate(mapping,
                                             dof_handler,
                                             QGauss<dim - 1>(
                                               dof_handler.get_fe().degree + 1),
                                             {},
                                             velocity,
                                             indicator);
          parallel::distributed::GridRefinement::
            refine_and_coarsen_fixed_number(tria,
                                            indicator,
                                            prm.refine_fraction,
                                            prm.coarsen_fraction);
        }

      RefinementFlags  flags;
      const Point<dim> centre = [] {
        Point<dim> c;
        for (unsigned int d = 0; d < dim; ++d)
          c[d] = 0.5;
        return c;
      }();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const Point<dim> x =
            mapping.transform_unit_to_real_cell(cell, centre);
          // Levels count from the initial mesh, which p4est may have refined
          // from a coarser one (geometry::initial_mesh_level).
          Assert(cell->level() >= initial_level, ExcInternalError());
          const unsigned int level = cell->level() - initial_level;
          // Size of the level-0 ancestor: children must not leave the band
          // just because they are smaller than the cell that entered it.
          const double       h0        = cell->diameter() * (1u << level);
          const unsigned int refine_to = band_level(x, h0, tools, 1.);
          // A child's centre lies at most h0/4 beyond its parent's: with the
          // margin h0 (not h0/2) a cell refined now is kept next time.
          const unsigned int keep_to =
            band_level(x, 2 * h0, tools, prm.coarsen_factor);
          const bool by_indicator =
            kelly && cell->refine_flag_set() && level < prm.indicator_level;
          const bool refine = level < refine_to || by_indicator;
          // A trimmed part's coarse cells may lie above the initial level.
          const bool coarsen =
            !refine && level > keep_to && cell->level() > 0 &&
            (!kelly || cell->coarsen_flag_set() || level > prm.indicator_level);
          cell->clear_refine_flag();
          cell->clear_coarsen_flag();
          if (refine)
            {
              cell->set_refine_flag();
              ++flags.refine;
            }
          else if (coarsen)
            {
              cell->set_coarsen_flag();
              ++flags.coarsen;
            }
        }
      flags.coarsen -= keep_shape(dof_handler, mapping);
      const MPI_Comm comm = tria.get_communicator();
      flags.refine        = Utilities::MPI::sum(flags.refine, comm);
      flags.coarsen       = Utilities::MPI::sum(flags.coarsen, comm);
      return flags;
    }

    template <int dim>
    unsigned int
    RefinementCriteria<dim>::keep_shape(const DoFHandler<dim> &dof_handler,
                                        const Mapping<dim>    &mapping) const
    {
      using Family = typename DoFHandler<dim>::cell_iterator;
      std::set<Family> families;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->coarsen_flag_set())
          families.insert(cell->parent());
      unsigned int cleared = 0;
      for (const auto &parent : families)
        {
          const unsigned int n     = parent->n_children();
          bool               whole = true;
          for (unsigned int k = 0; k < n; ++k)
            whole &= parent->child(k)->is_active() &&
                     parent->child(k)->is_locally_owned() &&
                     parent->child(k)->coarsen_flag_set();
          if (!whole) // p4est keeps it anyway
            continue;
          // Child k holds the parent's vertex k as its own vertex k.
          std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> corner;
          for (unsigned int k = 0; k < n; ++k)
            corner[k] = mapping.transform_unit_to_real_cell(
              parent->child(k),
              GeometryInfo<dim>::unit_cell_vertex(k));
          double deviation = 0;
          for (unsigned int k = 0; k < n; ++k)
            for (const unsigned int j : GeometryInfo<dim>::vertex_indices())
              {
                const Point<dim> xi =
                  0.5 * (GeometryInfo<dim>::unit_cell_vertex(k) +
                         GeometryInfo<dim>::unit_cell_vertex(j));
                Point<dim> coarse;
                for (unsigned int i = 0; i < n; ++i)
                  coarse += GeometryInfo<dim>::d_linear_shape_function(xi, i) *
                            corner[i];
                const Point<dim> x = mapping.transform_unit_to_real_cell(
                  parent->child(k),
                  GeometryInfo<dim>::unit_cell_vertex(j));
                deviation = std::max(deviation, x.distance(coarse));
              }
          if (deviation > prm.shape_tolerance)
            for (unsigned int k = 0; k < n; ++k)
              {
                parent->child(k)->clear_coarsen_flag();
                ++cleared;
              }
        }
      return cleared;
    }

#define INSTANTIATE(dim) template class RefinementCriteria<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace refinement
} // namespace formsolve
