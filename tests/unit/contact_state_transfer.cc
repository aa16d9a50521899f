// The contact state survives refinement and coarsening (refinement/adapt,
// State::transferable_fields): on the first tool every record is a linear
// function of the node's reference position, which nodal interpolation
// keeps exactly, at new and hanging nodes too; on the last tool the records
// are not smooth, and every node that persists must keep its values
// exactly, through refinement and back through coarsening. Flips and locks
// belong to one solve and start again. Run on 1 and 2 ranks (the nodes
// change owner).
#include <deal.II/base/mpi.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/refinement/adapt.h>

#include "check.h"
#include "small_blank.h"

#include <array>
#include <cmath>
#include <map>

using namespace dealii;
using namespace formsolve;

namespace
{
  using Values = std::array<double, 4>; // factor, scale, shift, active

  template <int dim>
  Values linear(const Point<dim> &x)
  {
    return {{1e3 * (2 + 0.3 * x[0] - 0.2 * x[1]),
             1.5 + 0.05 * x[0] + 0.1 * x[dim - 1],
             1e-3 * (20 + x[0] + 2 * x[1]),
             1.}};
  }

  template <int dim>
  Values rough(const Point<dim> &x)
  {
    const double h = std::sin(7.3 * x[0] + 3.1 * x[1] + 11.7 * x[dim - 1]);
    return {
      {1e4 * (1.5 + h), 1 + std::abs(h), 1e-3 * (1 + h), h > 0 ? 1. : 0.}};
  }

  Values values(const contact::ContactRecord &r)
  {
    return {{r.factor, r.scale, r.shift, r.active ? 1. : 0.}};
  }

  /// Position -> values of the last tool, gathered from all ranks.
  template <int dim>
  std::vector<std::pair<Point<dim>, Values>>
  gather(const state::State<dim> &state)
  {
    std::vector<std::pair<Point<dim>, Values>> local;
    const unsigned int                         last = state.tools.size() - 1;
    for (unsigned int k = 0; k < state.contact_set.nodes.size(); ++k)
      local.emplace_back(state.contact_set.nodes[k].reference_position,
                         values(state.contact_state(k, last)));
    std::vector<std::pair<Point<dim>, Values>> all;
    for (const auto &part : Utilities::MPI::all_gather(state.comm, local))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  struct Errors
  {
    double       linear = 0, kept = 0;
    unsigned int persisted = 0, fresh = 0, solve_memory = 0;
  };

  template <int dim>
  Errors compare(const state::State<dim>                          &state,
                 const std::vector<std::pair<Point<dim>, Values>> &before)
  {
    Errors             e;
    const unsigned int last = state.tools.size() - 1;
    for (unsigned int k = 0; k < state.contact_set.nodes.size(); ++k)
      {
        const auto  &x   = state.contact_set.nodes[k].reference_position;
        const Values lin = linear(x), got = values(state.contact_state(k, 0));
        for (unsigned int i = 0; i < 4; ++i)
          e.linear = std::max(e.linear, std::abs(got[i] / lin[i] - 1));
        const auto *old = static_cast<const Values *>(nullptr);
        for (const auto &[y, v] : before)
          if (x.distance(y) < 1e-9)
            old = &v;
        if (old == nullptr)
          ++e.fresh;
        else
          {
            ++e.persisted;
            const Values now = values(state.contact_state(k, last));
            for (unsigned int i = 0; i < 4; ++i)
              e.kept = std::max(e.kept,
                                std::abs(now[i] - (*old)[i]) /
                                  std::max(std::abs((*old)[i]), 1e-6));
          }
        for (unsigned int t = 0; t < state.tools.size(); ++t)
          e.solve_memory += state.contact_state(k, t).flips != 0 ||
                            state.contact_state(k, t).locked;
      }
    const MPI_Comm comm = state.comm;
    e.linear            = Utilities::MPI::max(e.linear, comm);
    e.kept              = Utilities::MPI::max(e.kept, comm);
    e.persisted         = Utilities::MPI::sum(e.persisted, comm);
    e.fresh             = Utilities::MPI::sum(e.fresh, comm);
    e.solve_memory      = Utilities::MPI::sum(e.solve_memory, comm);
    return e;
  }

  void report(const std::string &name, const Errors &e, const bool refined)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    test::close(name + ": linear records at every node (rel.)",
                e.linear,
                0,
                1e-12);
    test::close(name + ": persisting nodes keep their records (rel.)",
                e.kept,
                0,
                1e-12);
    std::cout << name << ": " << e.persisted << " persisting and " << e.fresh
              << " new contact nodes\n";
    test::close(name + ": nodes persisted (> 10)", e.persisted > 10, 1, 0);
    test::close(name + ": new nodes",
                refined ? e.fresh > 10 : e.fresh,
                refined ? 1 : 0,
                0);
    test::close(name + ": flips and locks reset", e.solve_memory, 0, 0);
  }

  template <int dim>
  void check(const std::string &name, const model::Model m)
  {
    test::SmallBlank<dim> blank(m, {1, 2, dim == 2 ? 4u : 2u});
    auto                 &state  = blank.state;
    const auto           &update = blank.update;
    AssertThrow(state.tools.size() >= 2, ExcInternalError());

    const unsigned int last = state.tools.size() - 1;
    for (unsigned int k = 0; k < state.contact_set.nodes.size(); ++k)
      {
        const auto &x = state.contact_set.nodes[k].reference_position;
        for (unsigned int t = 0; t <= last; ++t)
          {
            const Values v = t == 0 ? linear(x) : rough(x);
            auto        &r = state.contact_state(k, t);
            r.factor       = v[0];
            r.scale        = v[1];
            r.shift        = v[2];
            r.active       = v[3] > 0.5;
            r.flips        = 3;
            r.locked       = true;
          }
      }
    const auto original = gather(state);

    // No flags: the mesh stays, and the caller's hook (TimeLoop frees the
    // factors there) must not run.
    unsigned int hooks = 0;
    const auto   hook  = [&hooks]() { ++hooks; };
    auto         r     = refinement::adapt_flagged(state, update, hook);
    test::close(name + ": no flags, mesh unchanged", r.changed, 0, 0);
    test::close(name + ": no flags, no hook", hooks, 0, 0);

    // Refine the half of the blank nearer the axis (or corner).
    double extent = 0;
    for (const auto &cell : state.tria.active_cell_iterators())
      extent = std::max(extent, cell->center()[0]);
    extent = Utilities::MPI::max(extent, state.comm);
    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.5 * extent)
        cell->set_refine_flag();
    r = refinement::adapt_flagged(state, update, hook);
    AssertThrow(r.changed && r.cells_after > r.cells_before,
                ExcInternalError());
    test::close(name + ": refined, the hook ran once", hooks, 1, 0);
    report(name + ", refined", compare(state, original), true);

    // And back: the mesh, and every record, as at the start.
    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell->level() + 1 == int(state.tria.n_global_levels()))
        cell->set_coarsen_flag();
    r = refinement::adapt_flagged(state, update);
    AssertThrow(r.changed, ExcInternalError());
    report(name + ", coarsened", compare(state, original), false);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("axisymmetric", model::Model::axisymmetric);
  check<3>("quarter", model::Model::quarter);
  return test::result();
}
