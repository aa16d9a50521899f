// adaptive-strict at a hanging node: two master nodes carry F0 and F1 along
// the tool normal (-z), a third node hangs halfway between them (its z
// velocity the mean of theirs). The hanging node's estimate is its masters'
// factor per area, interpolated: (F0 + F1) / (2 delta) at unit areas. When
// the strict check finds it 3 delta deep, its factor must grow by the
// strict scale 1.1 * 3 = 3.3 in the next estimate, as any node's does,
// and the scale of a master must not leak into it. (A hanging node used to
// take its masters' scaled factors and drop its own scale: in the pan,
// prm/pan.prm, four nodes at the holder's edge stayed 3 um deep through
// every strict pass.)
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <formsolve/contact/strategies/adaptive.h>

#include "check.h"
#include "flat_punch.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double       delta = 1e-3, dt = 0.25, F0 = 300, F1 = 500;
  const unsigned int n_dofs = 9; // three nodes, x y z each

  struct Masters
  {
    IndexSet                       all{n_dofs};
    TrilinosWrappers::SparseMatrix K;
    TrilinosWrappers::MPI::Vector  r;
    AffineConstraints<double>      constraints;
    contact::ContactSet<3>         set;

    Masters()
    {
      all.add_range(0, n_dofs);
      constraints.reinit(all);
      // Node 2's z velocity is the mean of nodes 0 and 1.
      constraints.add_line(8);
      constraints.add_entry(8, 2, 0.5);
      constraints.add_entry(8, 5, 0.5);
      constraints.close();
      DynamicSparsityPattern dsp(n_dofs, n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        dsp.add(i, i);
      K.reinit(all, all, dsp, MPI_COMM_WORLD);
      for (unsigned int i = 0; i < n_dofs; ++i)
        K.set(i, i, 1.);
      K.compress(VectorOperation::insert);
      r.reinit(all, MPI_COMM_WORLD);
      // The tool presses along -z: n.r = F means r_z = -F.
      r[2] = -F0;
      r[5] = -F1;
      r.compress(VectorOperation::insert);
      set.nodes.resize(3);
      for (unsigned int v = 0; v < 3; ++v)
        {
          set.nodes[v].dofs = {{3 * v, 3 * v + 1, 3 * v + 2}};
          contact::ContactPair<3> pair;
          pair.node = v, pair.tool = 0, pair.area = 1;
          pair.normal[2]     = -1;
          pair.predicted_gap = -0.5 * delta;
          pair.active        = true;
          set.pairs.push_back(pair);
        }
    }

    contact::SystemView system()
    {
      return contact::SystemView{&r, &K, &constraints, dt, false};
    }
  };
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const parameters::Tools tool_prm = test::flat_punch_only(delta);
  parameters::Contact     prm      = test::undamped_adaptive(delta);
  prm.lower_bound                  = 1e-9;
  prm.upper_bound                  = 1e9;
  prm.freeze                       = true;
  prm.factor_update                = parameters::FactorUpdate::iteration;
  const tools::ToolSet<3> tools(tool_prm, prm, 1.);

  Masters                     s;
  contact::AdaptivePenalty<3> adaptive(prm, true);
  contact::ContactState       state;
  state.reset(3, tools.size());
  std::vector<double> eps;
  const double        interpolated = 0.5 * (F0 + F1) / delta;

  adaptive.begin_solve();
  adaptive.estimate(s.set, tools, s.system(), state, eps);
  test::close("master 0: F0/delta (N/mm)", eps[0], F0 / delta, 1e-6);
  test::close("master 1: F1/delta (N/mm)", eps[1], F1 / delta, 1e-6);
  test::close("hanging node: its masters' mean (N/mm)",
              eps[2],
              interpolated,
              1e-6);

  // The strict check: master 0 and the hanging node are 2 and 3 delta deep.
  s.set.pairs[0].predicted_gap = -2 * delta;
  s.set.pairs[2].predicted_gap = -3 * delta;
  const bool again = adaptive.tighten(s.set, tools, state, MPI_COMM_WORLD);
  test::close("strict check asks for another pass", again, 1, 0);
  adaptive.begin_solve();
  adaptive.estimate(s.set, tools, s.system(), state, eps);
  test::close("master 0 scaled by 1.1 * 2 (N/mm)",
              eps[0],
              2.2 * F0 / delta,
              1e-6);
  test::close("master 1 unscaled (N/mm)", eps[1], F1 / delta, 1e-6);
  test::close("hanging node scaled by its own 1.1 * 3 (N/mm)",
              eps[2],
              3.3 * interpolated,
              1e-6);
  test::close("hanging node's record: the unscaled estimate (N/mm)",
              state(2, 0).factor,
              interpolated,
              1e-6);
  return test::result();
}
