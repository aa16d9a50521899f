#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/adaptation_strategies.h>

#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/parameters/require.h>
#include <formsolve/refinement/adapt.h>
#include <formsolve/trimming/trim_cells.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace formsolve
{
  namespace trimming
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      using Cell = typename Triangulation<dim>::active_cell_iterator;

      /// The cell's vertices in the current configuration.
      template <int dim>
      std::vector<Point<dim>> vertices(const state::State<dim> &state,
                                       const Cell<dim>         &cell)
      {
        const auto x = state.mapping->get_vertices(cell); // cached
        return std::vector<Point<dim>>(x.begin(), x.end());
      }

      template <int dim>
      Point<dim> centre(const std::vector<Point<dim>> &x)
      {
        Point<dim> c;
        for (const auto &p : x)
          c += p / double(x.size());
        return c;
      }

      /// The largest |side| at the vertices of a cell the line crosses,
      /// or 0 if it does not cross it.
      template <int dim>
      double crossing(const TrimShape<dim>          &shape,
                      const std::vector<Point<dim>> &x)
      {
        double low = 1e300, high = -1e300, far = 0;
        for (const auto &p : x)
          {
            const double s = shape.side(p);
            low            = std::min(low, s);
            high           = std::max(high, s);
            far            = std::max(far, std::abs(s));
          }
        return low <= 0 && high > 0 ? far : 0;
      }

      /// Flags the cells the line crosses whose nodes lie further than
      /// @p tolerance from it (with @p set; else only measures). Returns the
      /// number flagged and the largest crossing distance (all ranks).
      template <int dim>
      std::pair<unsigned int, double> flag_line(state::State<dim>    &state,
                                                const TrimShape<dim> &shape,
                                                const double          tolerance,
                                                const bool            set)
      {
        unsigned int n   = 0;
        double       far = 0;
        for (const auto &cell : state.tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double d = crossing(shape, vertices(state, cell));
              far            = std::max(far, d);
              if (set && d > tolerance)
                {
                  cell->set_refine_flag();
                  ++n;
                }
            }
        return {Utilities::MPI::sum(n, state.comm),
                Utilities::MPI::max(far, state.comm)};
      }

      /// Flags the cut-away cells coarser than a kept cell they share a
      /// vertex with (@p kept on owned and ghost cells), so that no kept
      /// node hangs on cut-away cells only. Returns the number flagged (all
      /// ranks).
      template <int dim>
      unsigned int flag_neighbours(state::State<dim> &state,
                                   const KeptCells   &kept)
      {
        const auto   touches = GridTools::vertex_to_cell_map(state.tria);
        unsigned int n       = 0;
        for (const auto &cell : state.tria.active_cell_iterators())
          if (cell->is_locally_owned() && !kept[cell->active_cell_index()] &&
              !cell->refine_flag_set())
            for (const unsigned int v : cell->vertex_indices())
              for (const auto &other : touches[cell->vertex_index(v)])
                if (!other->is_artificial() &&
                    kept[other->active_cell_index()] &&
                    other->level() > cell->level() && !cell->refine_flag_set())
                  {
                    cell->set_refine_flag();
                    ++n;
                  }
        return Utilities::MPI::sum(n, state.comm);
      }

      /// Refines the flagged cells; their children take their parent's side
      /// of @p kept, which then holds the new mesh's cells (owned and
      /// ghost).
      template <int dim>
      bool refine_keeping_sides(state::State<dim>               &state,
                                const state::HistoryUpdate<dim> &update,
                                KeptCells                       &kept)
      {
        auto         &tria = state.tria;
        Vector<float> sides(tria.n_active_cells());
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            sides[cell->active_cell_index()] = kept[cell->active_cell_index()];
        parallel::distributed::CellDataTransfer<dim, dim, Vector<float>>
                   transfer(tria,
                   false,
                   &AdaptationStrategies::Refinement::preserve<dim, dim, float>,
                   &AdaptationStrategies::Coarsening::max<dim, dim, float>);
        const auto a = refinement::adapt_flagged(
          state,
          update,
          [&]() { transfer.prepare_for_coarsening_and_refinement(sides); },
          /*measure=*/false);
        if (!a.changed)
          return false;
        Vector<float> after(tria.n_active_cells());
        transfer.unpack(after);
        kept.assign(tria.n_active_cells(), false);
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            kept[cell->active_cell_index()] =
              after[cell->active_cell_index()] > 0.5f;
        GridTools::exchange_cell_data_to_ghosts<char, Triangulation<dim>>(
          tria,
          [&](const auto &cell) -> std::optional<char> {
            return char(kept[cell->active_cell_index()]);
          },
          [&](const auto &cell, const char side) {
            kept[cell->active_cell_index()] = side != 0;
          });
        return true;
      }

      template <int dim>
      std::pair<double, double> kept_integrals(const state::State<dim> &state,
                                               const KeptCells         &kept)
      {
        model::CellKinematics<dim> k(state.kinematics,
                                     *state.mapping,
                                     state.dof_handler.get_fe(),
                                     state.history_rule);
        double                     volume = 0, strain = 0;
        for (const auto &cell : state.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && kept[cell->active_cell_index()])
            {
              k.reinit(cell);
              const auto h = state.history.get_data(cell);
              for (unsigned int q = 0; q < k.n_points(); ++q)
                {
                  volume += k.dV(q);
                  strain += h[q]->strain * k.dV(q);
                }
            }
        return {Utilities::MPI::sum(volume, state.comm),
                Utilities::MPI::sum(strain, state.comm)};
      }
    } // namespace

    template <int dim>
    KeptCells kept_cells(const state::State<dim> &state,
                         const TrimShape<dim>    &shape)
    {
      KeptCells kept(state.tria.n_active_cells(), false);
      for (const auto &cell : state.tria.active_cell_iterators())
        if (!cell->is_artificial())
          kept[cell->active_cell_index()] =
            shape.side(centre(vertices(state, cell))) > 0;
      return kept;
    }

    template <int dim>
    TrimReport trim_part(state::State<dim>               &state,
                         const TrimShape<dim>            &shape,
                         const parameters::Trimming      &trimming,
                         const state::HistoryUpdate<dim> &update,
                         KeptCells                       &kept)
    {
      TrimReport report;
      report.cells_before = state.tria.n_global_active_cells();
      report.volume_before =
        kept_integrals(state, KeptCells(state.tria.n_active_cells(), true))
          .first;
      // Each pass halves the cells the line crosses (their cut-away
      // neighbours come along); the part is the cells whose centres lie on
      // its side.
      for (; report.passes < trimming.max_passes; ++report.passes)
        {
          const auto n = flag_line(state, shape, trimming.tolerance, true);
          if (n.first == 0)
            break;
          flag_neighbours(state, kept_cells(state, shape));
          if (!refinement::adapt_flagged(state, update, {}, false).changed)
            break;
        }
      report.edge_deviation =
        flag_line(state, shape, trimming.tolerance, false).second;
      // Then the part stays as it is: cut-away cells refined to match a
      // finer kept neighbour keep their side in their children (by their
      // centres, those across the line would join the part, and refine the
      // line further with each pass).
      kept = kept_cells(state, shape);
      while (flag_neighbours(state, kept) > 0 &&
             refine_keeping_sides(state, update, kept))
        {}
      report.cells_after  = state.tria.n_global_active_cells();
      unsigned int n_kept = 0;
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned() && kept[cell->active_cell_index()])
          ++n_kept;
      report.cells_kept = Utilities::MPI::sum(double(n_kept), state.comm);
      std::tie(report.volume_kept, report.strain_kept) =
        kept_integrals(state, kept);
      return report;
    }

    template <int dim>
    void check_trim_curve(const state::State<dim>    &state,
                          const parameters::Trimming &trimming)
    {
      // Reading the files is the first check.
      const TrimShape<dim> all(trimming, state.prm.geometry.model, state.comm);
      if (trimming.curve_file.empty())
        return;
      parameters::Trimming curve_only;
      curve_only.curve_file = trimming.curve_file;
      curve_only.curve_side = trimming.curve_side;
      const TrimShape<dim> curve(curve_only,
                                 state.prm.geometry.model,
                                 state.comm);
      const KeptCells      kept = kept_cells(state, curve);
      unsigned int         in = 0, out = 0;
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          ++(kept[cell->active_cell_index()] ? in : out);
      in  = Utilities::MPI::sum(in, state.comm);
      out = Utilities::MPI::sum(out, state.comm);
      parameters::require(in > 0 && out > 0,
                          "Trimming/Curve file",
                          "the curve in " + trimming.curve_file +
                            " misses the blank: it keeps " +
                            (in > 0 ? "all" : "none") +
                            " of it (x, y in mm, the part's coordinates; "
                            "Curve keeps = " +
                            parameters::name(trimming.curve_side) + ")");
    }

    template <int dim>
    std::vector<Point<dim>> cut_faces(const state::State<dim> &state,
                                      const KeptCells         &kept)
    {
      std::vector<Point<dim>> centres;
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned() && kept[cell->active_cell_index()])
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f))
              {
                const auto other = cell->neighbor(f);
                // Conforming across the cut (trim_part): the neighbour is
                // active and as fine as the cell.
                if (other->is_active() && !kept[other->active_cell_index()])
                  {
                    Point<dim> unit;
                    for (unsigned int d = 0; d < dim; ++d)
                      unit[d] = 0.5;
                    unit[GeometryInfo<dim>::unit_normal_direction[f]] = f % 2;
                    centres.push_back(
                      state.mapping->transform_unit_to_real_cell(cell, unit));
                  }
              }
      return centres;
    }

#define INSTANTIATE(dim)                                                        \
  template TrimReport              trim_part(state::State<dim> &,               \
                                             const TrimShape<dim> &,            \
                                             const parameters::Trimming &,      \
                                             const state::HistoryUpdate<dim> &, \
                                             KeptCells &);                      \
  template KeptCells               kept_cells(const state::State<dim> &,        \
                                              const TrimShape<dim> &);          \
  template std::vector<Point<dim>> cut_faces(const state::State<dim> &,         \
                                             const KeptCells &);                \
  template void                    check_trim_curve(const state::State<dim> &,  \
                                                    const parameters::Trimming &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace trimming
} // namespace formsolve
