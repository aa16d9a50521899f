// The quadrature history through refinement and coarsening
// (refinement/history_transfer.cc, refinement/adapt.cc) on a sheet bent by a
// non-affine displacement: a damage field with one spike and a strain field
// that jumps from cell to cell get no new maximum or minimum, the spike is
// not smoothed away, and the integrals over the sheet (reference
// configuration) are kept; the volume error that the volume correction
// removes (ln dV/dV0 less the cell's offset) of a new cell is that of the
// cell it came from, through refinement and back through coarsening, while
// the sheet's volume stays. A plain L2 projection overshoots the spike, a
// limited one flattens it; refinement without the offset exchange shows each
// child its own part of the parent's volume error. Run on 1 and 2 ranks.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/refinement/adapt.h>
#include <formsolve/state/sheet_integrals.h>

#include "check.h"
#include "small_blank.h"

#include <cmath>
#include <map>

using namespace dealii;
using namespace formsolve;

namespace
{
  using History = state::QuadraturePointHistory;

  /// A displacement that bends and stretches the sheet unevenly (mm), in
  /// Q1 on every cell (products of distinct coordinates), so that coarsening
  /// keeps the geometry too.
  template <int dim>
  class Bend : public Function<dim>
  {
  public:
    Bend()
        : Function<dim>(dim)
    {}
    double value(const Point<dim> &x, const unsigned int c) const override
    {
      const double z = x[dim - 1];
      if (c == dim - 1)
        return 0.01 * x[0] * x[1] + 0.05 * x[0] * z;
      if (dim == 2)
        return 0.03 * x[0] * x[1];
      return c == 0 ? 0.004 * x[0] * x[1] + 0.03 * x[0] * z
                    : 0.004 * x[0] * x[1] + 0.03 * x[1] * z;
    }
  };

  template <int dim>
  bool spike_cell(const typename Triangulation<dim>::cell_iterator &cell)
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = d == dim - 1 ? 0.6 : 2.6;
    return cell->point_inside(p);
  }

  struct Extremes
  {
    double min = 1e300, max = -1e300;
  };

  template <int dim>
  Extremes extremes(const state::State<dim> &state,
                    const double History::*field)
  {
    Extremes e;
    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &h : state.history.get_data(cell))
          {
            e.min = std::min(e.min, (*h).*field);
            e.max = std::max(e.max, (*h).*field);
          }
    e.min = -Utilities::MPI::max(-e.min, state.comm);
    e.max = Utilities::MPI::max(e.max, state.comm);
    return e;
  }

  using Key = std::vector<double>;

  template <int dim>
  Key key(const Point<dim> &p)
  {
    return Key(p.begin_raw(), p.end_raw());
  }

  /// The volume error of every locally owned cell, with the cell.
  template <int dim>
  std::vector<std::pair<typename Triangulation<dim>::cell_iterator, double>>
  volume_errors(state::State<dim>               &state,
                const state::HistoryUpdate<dim> &update)
  {
    // The exchange turns offsets into errors; a second one turns them back.
    update.exchange_volume_offsets(state.dof_handler,
                                   *state.mapping,
                                   state.history);
    std::vector<std::pair<typename Triangulation<dim>::cell_iterator, double>>
      e;
    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned())
        e.emplace_back(cell, state.history.get_data(cell)[0]->volume_offset);
    update.exchange_volume_offsets(state.dof_handler,
                                   *state.mapping,
                                   state.history);
    return e;
  }

  /// What the transfer must keep.
  struct Measures
  {
    Extremes oyane, strain;
    double   oyane_integral, strain_integral; // over dV0
  };

  template <int dim>
  Measures measure(const state::State<dim> &state)
  {
    const auto &ref = state.reference_mapping;
    return {extremes(state, &History::oyane),
            extremes(state, &History::strain),
            integral(state, &History::oyane, &ref),
            integral(state, &History::strain, &ref)};
  }

  template <int dim>
  void check_adaptation(const std::string               &name,
                        state::State<dim>               &state,
                        const state::HistoryUpdate<dim> &update,
                        const bool                       refine)
  {
    const auto before_values = measure(state);
    // Before: by each cell's reference centre, from all ranks (cells move
    // between ranks with the new partition).
    std::vector<std::pair<Key, double>> local;
    for (const auto &[cell, e] : volume_errors(state, update))
      local.emplace_back(key<dim>(cell->center()), e);
    std::map<Key, double> before;
    for (const auto &part : Utilities::MPI::all_gather(state.comm, local))
      before.insert(part.begin(), part.end());

    const auto r = refinement::adapt_flagged(state, update);
    AssertThrow(r.changed, ExcInternalError());

    const auto after_values = measure(state);
    // A cell left alone against itself, a child against its parent, a
    // parent against the mean of its children (equal reference volumes).
    double       mismatch = 0, largest = 0;
    unsigned int compared = 0;
    for (const auto &[cell, e] : volume_errors(state, update))
      {
        double expected = 0;
        if (before.count(key<dim>(cell->center())))
          expected = before.at(key<dim>(cell->center()));
        else if (refine && before.count(key<dim>(cell->parent()->center())))
          expected = before.at(key<dim>(cell->parent()->center()));
        else if (!refine)
          {
            unsigned int n = 0;
            for (const auto &[centre, old] : before)
              {
                Point<dim> c;
                for (unsigned int d = 0; d < dim; ++d)
                  c[d] = centre[d];
                if (cell->point_inside(c))
                  {
                    expected += old;
                    ++n;
                  }
              }
            AssertThrow(n == GeometryInfo<dim>::max_children_per_cell,
                        ExcInternalError());
            expected /= n;
          }
        else
          AssertThrow(false, ExcInternalError());
        mismatch = std::max(mismatch, std::abs(e - expected));
        largest  = std::max(largest, std::abs(e));
        ++compared;
      }
    mismatch = Utilities::MPI::max(mismatch, state.comm);
    largest  = Utilities::MPI::max(largest, state.comm);
    compared = Utilities::MPI::sum(compared, state.comm);

    if (Utilities::MPI::this_mpi_process(state.comm) != 0)
      return;
    std::cout << name << ": damage in [" << after_values.oyane.min << ", "
              << after_values.oyane.max << "] from [" << before_values.oyane.min
              << ", " << before_values.oyane.max << "], strain in ["
              << after_values.strain.min << ", " << after_values.strain.max
              << "] from [" << before_values.strain.min << ", "
              << before_values.strain.max << "]\n";
    test::close(name + ": no new damage maximum",
                after_values.oyane.max <= before_values.oyane.max + 1e-12,
                1,
                0);
    test::close(name + ": the damage peak is not smoothed away (> 0.99)",
                after_values.oyane.max >= 0.99 * before_values.oyane.max,
                1,
                0);
    test::close(name + ": no new damage minimum",
                after_values.oyane.min >= before_values.oyane.min - 1e-12,
                1,
                0);
    test::close(name + ": no new strain maximum",
                after_values.strain.max <= before_values.strain.max + 1e-12,
                1,
                0);
    test::close(name + ": no new strain minimum",
                after_values.strain.min >= before_values.strain.min - 1e-12,
                1,
                0);
    test::close(name + ": int I dV0 kept (rel.)",
                after_values.oyane_integral / before_values.oyane_integral - 1,
                0,
                1e-10);
    test::close(name + ": int eps dV0 kept (rel.)",
                after_values.strain_integral / before_values.strain_integral -
                  1,
                0,
                1e-10);
    test::close(name + ": volume kept (rel.)",
                r.volume_after / r.volume_before - 1,
                0,
                1e-12);
    std::cout << name << ": largest volume error " << largest << " over "
              << compared << " cells\n";
    test::close(name + ": the volume error is not trivially zero",
                largest > 1e-4,
                1,
                0);
    test::close(name + ": new cells keep the volume error", mismatch, 0, 1e-9);
  }

  template <int dim>
  void check(const std::string &name, const model::Model m)
  {
    test::SmallBlank<dim> blank(m, {1, 2, dim == 2 ? 4u : 2u});
    auto                 &state  = blank.state;
    const auto           &update = blank.update;

    VectorTools::interpolate(state.reference_mapping,
                             state.dof_handler,
                             Bend<dim>(),
                             state.displacement);
    state.constraints.distribute(state.displacement);
    state.displacement_ghost = state.displacement;
    state.update_mapping();

    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto   h    = state.history.get_data(cell);
          const double jump = cell->center()[0] < 4 ? 0.5 : 0.1;
          for (unsigned int q = 0; q < h.size(); ++q)
            {
              h[q]->oyane  = spike_cell<dim>(cell) && q == 0 ? 1. : 0.2;
              h[q]->strain = jump + 0.01 * q;
            }
        }

    // Refine the half of the blank nearer the axis (or corner), where the
    // spike is.
    double extent = 0;
    for (const auto &cell : state.tria.active_cell_iterators())
      extent = std::max(extent, cell->center()[0]);
    extent = Utilities::MPI::max(extent, state.comm);
    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.5 * extent)
        cell->set_refine_flag();
    check_adaptation(name + ", refined", state, update, true);

    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell->level() + 1 == int(state.tria.n_global_levels()))
        cell->set_coarsen_flag();
    check_adaptation(name + ", coarsened", state, update, false);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("axisymmetric", model::Model::axisymmetric);
  check<3>("quarter", model::Model::quarter);
  return test::result();
}
