// The 1-D spring of the method page (../shared/method/adaptive-penalty.md):
// stiffness k, force q, rigid face at u_bar. The adaptive estimator must
// return the closed-form minimal factor eps = (q - k (u_bar + delta)) / delta
// to round-off, and with it the penetration is exactly delta.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <formsolve/contact/strategies/adaptive.h>

#include "check.h"
#include "flat_punch.h"

using namespace dealii;
using namespace formsolve;

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double k = 100, q = 1000, u_bar = 2, delta = 1e-3, dt = 0.25;

  // Velocity form with u = v dt: r_b(v) = k v dt - q, K_b = k dt. The spring
  // is DoF 0; DoFs 1, 2 are uncoupled unit springs (the node's other axes).
  IndexSet all(3);
  all.add_range(0, 3);
  DynamicSparsityPattern dsp(3, 3);
  for (unsigned int i = 0; i < 3; ++i)
    dsp.add(i, i);
  TrilinosWrappers::SparseMatrix K;
  K.reinit(all, all, dsp, MPI_COMM_WORLD);
  K.set(0, 0, k * dt);
  K.set(1, 1, 1.);
  K.set(2, 2, 1.);
  K.compress(VectorOperation::insert);

  AffineConstraints<double> constraints;
  constraints.close();

  const parameters::Tools tool_prm    = test::flat_punch_only(delta);
  parameters::Contact     contact_prm = test::undamped_adaptive(delta);
  contact_prm.lower_bound             = 1e-3;
  contact_prm.upper_bound             = 1e6;

  const tools::ToolSet<3> tools(tool_prm, contact_prm, 1.);

  // projection (the published method) at iterates inside and short of the
  // final position: the estimate must not depend on where the iteration
  // stands; force (its dv -> 0 limit) at the converged iterate u_bar + delta.
  using parameters::AdaptiveEstimate;
  for (const auto &[variant, u] :
       {std::pair{AdaptiveEstimate::projection, u_bar + 0.5},
        std::pair{AdaptiveEstimate::projection, u_bar + 1e-6},
        std::pair{AdaptiveEstimate::force, u_bar + delta}})
    {
      contact_prm.adaptive_estimate = variant;
      const std::string name =
        variant == AdaptiveEstimate::force ? "force" : "projection";
      contact::ContactSet<3> set;
      set.nodes.resize(1);
      set.nodes[0].dofs = {{0, 1, 2}};
      contact::ContactPair<3> pair;
      pair.node = 0, pair.tool = 0, pair.area = 1;
      pair.normal[0]     = -1; // the face pushes towards -x
      pair.gap           = u_bar;
      pair.predicted_gap = u_bar - u;
      pair.active        = true;
      set.pairs.push_back(pair);

      TrilinosWrappers::MPI::Vector r(all, MPI_COMM_WORLD);
      r[0] = k * u - q;
      r.compress(VectorOperation::insert);

      contact::AdaptivePenalty<3> estimator(contact_prm, false);
      contact::ContactState       state;
      state.reset(1, tools.size());
      std::vector<double> eps;
      estimator.estimate(set,
                         tools,
                         contact::SystemView{&r, &K, &constraints, dt},
                         state,
                         eps);
      const double eps_min = (q - k * (u_bar + delta)) / delta;
      test::close(name + ": eps at u = " + std::to_string(u) +
                    " / closed-form minimum",
                  eps[0] / eps_min,
                  1.,
                  1e-12);

      // k u + eps (u - u_bar) = q  =>  penetration u - u_bar.
      const double u_solved = (q + eps[0] * u_bar) / (k + eps[0]);
      test::close("penetration / delta", (u_solved - u_bar) / delta, 1., 1e-9);
    }

  // adaptive-strict: the persistent scale acts within the bounds (Upper bound
  // bounds eps), and relaxes towards 1 where the node sits far inside delta.
  {
    contact::ContactSet<3> set;
    set.nodes.resize(1);
    set.nodes[0].dofs = {{0, 1, 2}};
    contact::ContactPair<3> pair;
    pair.node = 0, pair.tool = 0, pair.area = 1;
    pair.normal[0]     = -1;
    pair.gap           = u_bar;
    pair.predicted_gap = -delta;
    pair.active        = true;
    set.pairs.push_back(pair);
    TrilinosWrappers::MPI::Vector r(all, MPI_COMM_WORLD);
    r[0] = k * (u_bar + delta) - q;
    r.compress(VectorOperation::insert);

    contact_prm.adaptive_estimate = parameters::AdaptiveEstimate::force;
    contact::AdaptivePenalty<3> strict(contact_prm, true);
    contact::ContactState       state;
    state.reset(1, tools.size());
    state(0, 0).scale = 1e3; // eps_min * 1e3 = 8e8 > Upper bound * k = 1e8
    std::vector<double> eps;
    strict.estimate(set,
                    tools,
                    contact::SystemView{&r, &K, &constraints, dt},
                    state,
                    eps);
    test::close("strict eps / (Upper bound * K/dt)",
                eps[0] / (contact_prm.upper_bound * k),
                1.,
                1e-12);

    state(0, 0).scale          = 4;
    set.pairs[0].predicted_gap = -0.1 * delta; // far inside delta
    test::close("no re-solve inside delta",
                strict.finish_solve(set, tools, state, MPI_COMM_WORLD),
                0,
                0);
    test::close("scale halved towards 1", state(0, 0).scale, 2., 1e-15);
    set.pairs[0].predicted_gap = -2 * delta; // twice too deep
    test::close("re-solve beyond delta",
                strict.finish_solve(set, tools, state, MPI_COMM_WORLD),
                1,
                0);
    test::close("scale raised by 1.1 depth/delta",
                state(0, 0).scale,
                4.4,
                1e-12);
  }
  return test::result();
}
