// When the adaptive factors are estimated (Contact/Factor update), on the
// 1-D spring of adaptive_penalty_spring: a node carrying the force F has the
// estimate F/delta. Checked:
// - iteration: a step's predictor keeps the record; the next iterate is
//   estimated; 'iteration and predictor' estimates at the predictor too;
// - step: held through a solve whatever the residual; converged() writes the
//   next solve's factor;
// - freeze: a pair locked by the chatter guard that flips does not restart
//   the estimates;
// - the body system is read (its tangent assembled) only where a strategy
//   needs it: never by the fixed penalty, not at an iterate whose factors
//   the adaptive one holds, not at a trial with the iterate's pairs; and
//   at most once per point.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <formsolve/contact/strategies/adaptive.h>
#include <formsolve/contact/strategies/fixed.h>

#include "check.h"
#include "flat_punch.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double k = 100, delta = 1e-3, dt = 0.25;

  struct Spring
  {
    IndexSet                       all{3};
    TrilinosWrappers::SparseMatrix K;
    TrilinosWrappers::MPI::Vector  r;
    AffineConstraints<double>      constraints;
    contact::ContactSet<3>         set;

    Spring()
    {
      all.add_range(0, 3);
      DynamicSparsityPattern dsp(3, 3);
      for (unsigned int i = 0; i < 3; ++i)
        dsp.add(i, i);
      K.reinit(all, all, dsp, MPI_COMM_WORLD);
      K.set(0, 0, k * dt);
      K.set(1, 1, 1.);
      K.set(2, 2, 1.);
      K.compress(VectorOperation::insert);
      constraints.close();
      r.reinit(all, MPI_COMM_WORLD);
      set.nodes.resize(1);
      set.nodes[0].dofs = {{0, 1, 2}};
      contact::ContactPair<3> pair;
      pair.node = 0, pair.tool = 0, pair.area = 1;
      pair.normal[0]     = -1;
      pair.predicted_gap = -delta;
      pair.active        = true;
      set.pairs.push_back(pair);
    }

    /// The node carries @p force (N) along the tool normal: n.r_b = force,
    /// n = -e_x; at a step's predictor if @p predictor.
    contact::SystemView carry(const double force, const bool predictor = false)
    {
      r[0] = -force;
      r.compress(VectorOperation::insert);
      return contact::SystemView{&r, &K, &constraints, dt, predictor};
    }

    /// As carry(), read lazily: @p reads counts the assemblies it asks for.
    contact::SystemView
    lazy(const double force, unsigned int &reads, const bool predictor = false)
    {
      r[0] = -force;
      r.compress(VectorOperation::insert);
      return contact::SystemView(&r,
                                 &K,
                                 &constraints,
                                 dt,
                                 predictor,
                                 [&reads]() { ++reads; });
    }
  };
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const parameters::Tools tool_prm = test::flat_punch_only(delta);
  parameters::Contact     prm      = test::undamped_adaptive(delta);
  prm.lower_bound                  = 1e-6;
  prm.upper_bound                  = 1e6;
  const tools::ToolSet<3> tools(tool_prm, prm, 1.);
  const double            record = 2e5; // N/mm, from an earlier solve

  using parameters::FactorUpdate;
  for (const auto update : {FactorUpdate::iteration,
                            FactorUpdate::and_predictor,
                            FactorUpdate::step})
    {
      const std::string name = update == FactorUpdate::iteration ? "iteration"
                               : update == FactorUpdate::step
                                 ? "step"
                                 : "iteration and predictor";
      prm.factor_update      = update;
      Spring                      s;
      contact::AdaptivePenalty<3> adaptive(prm, false);
      contact::ContactState       state;
      state.reset(1, tools.size());
      state(0, 0).factor = record;
      std::vector<double> eps;

      adaptive.begin_solve();
      // FormingSystem may estimate twice at the predictor (a new pair set,
      // then Newton's update): both must keep the record.
      for (const double force : {500., 600.})
        {
          adaptive.estimate(s.set, tools, s.carry(force, true), state, eps);
          test::close(name + ": at the predictor (N/mm)",
                      eps[0],
                      update == FactorUpdate::and_predictor ? force / delta
                                                            : record,
                      1e-6);
        }
      adaptive.estimate(s.set, tools, s.carry(300), state, eps);
      test::close(name + ": at the next iterate (N/mm)",
                  eps[0],
                  update == FactorUpdate::step ? record : 300 / delta,
                  1e-6);
      adaptive.converged(s.set, tools, s.carry(400), state);
      adaptive.begin_solve();
      adaptive.estimate(s.set, tools, s.carry(100), state, eps);
      test::close(name + ": next solve's first iterate (N/mm)",
                  eps[0],
                  update == FactorUpdate::step ? 400 / delta : 100 / delta,
                  1e-6);
    }

  // Freeze: the pair is locked and flips (active -> open) between two
  // estimates; the factors must stay those of the first.
  {
    prm.factor_update = FactorUpdate::iteration;
    prm.freeze        = true;
    Spring                      s;
    contact::AdaptivePenalty<3> adaptive(prm, false);
    contact::ContactState       state;
    state.reset(1, tools.size());
    std::vector<double> eps;
    adaptive.begin_solve();
    adaptive.estimate(s.set, tools, s.carry(500), state, eps); // unlocked
    adaptive.estimate(s.set, tools, s.carry(300), state, eps);
    s.set.pairs[0].locked = true;
    adaptive.estimate(s.set, tools, s.carry(200), state, eps);
    const double first_locked = eps[0];
    s.set.pairs[0].active     = false;
    adaptive.estimate(s.set, tools, s.carry(100), state, eps);
    test::close("locked pair flipped: factor frozen (N/mm)",
                eps[0],
                first_locked,
                1e-6);
  }

  // Reads of the body system.
  {
    Spring                s;
    std::vector<double>   eps;
    unsigned int          reads = 0;
    contact::ContactState state;
    state.reset(1, tools.size());
    contact::FixedPenalty<3> fixed;
    fixed.at_point(s.set, tools, s.lazy(500, reads), state, eps, false);
    test::close("fixed: factor from the tool alone (N/mm)",
                eps[0],
                tools.penalty_factor(0) * s.set.pairs[0].area,
                1e-9);
    test::close("fixed: at_iterate estimates nothing",
                fixed.at_iterate(s.set, tools, s.lazy(500, reads), state, eps),
                0,
                0);
    test::close("fixed: body system read", reads, 0, 0);

    for (const auto update : {FactorUpdate::iteration, FactorUpdate::step})
      {
        const std::string name =
          update == FactorUpdate::step ? "step: " : "iteration: ";
        prm.factor_update = update;
        prm.freeze        = false;
        contact::AdaptivePenalty<3> adaptive(prm, false);
        state.reset(1, tools.size());
        state(0, 0).factor = record;
        adaptive.begin_solve();
        reads = 0;
        // A new pair at the predictor: estimated at once, one read however
        // often the system is looked at.
        adaptive
          .at_point(s.set, tools, s.lazy(500, reads, true), state, eps, false);
        test::close(name + "new pairs read the system once", reads, 1, 0);
        // A trial with the iterate's pairs keeps their factors.
        const double kept = eps[0];
        adaptive.at_point(s.set, tools, s.lazy(700, reads), state, eps, true);
        test::close(name + "same pairs: no read", reads, 1, 0);
        test::close(name + "same pairs: factor kept", eps[0], kept, 0);
        // Accepted: iteration estimates anew (a read); step holds them.
        const bool estimated =
          adaptive.at_iterate(s.set, tools, s.lazy(300, reads), state, eps);
        const bool step = update == FactorUpdate::step;
        test::close(name + "iterate estimated", estimated, !step, 0);
        test::close(name + "iterate's reads", reads, step ? 1 : 2, 0);
        test::close(name + "iterate's factor (N/mm)",
                    eps[0],
                    step ? record : 300 / delta,
                    1e-6);
        // Convergence: step reads the system for the next solve's factors
        // (one more read), iteration reads nothing.
        const unsigned int before = reads;
        adaptive.converged(s.set, tools, s.lazy(400, reads), state);
        test::close(name + "converged reads", reads - before, step ? 1 : 0, 0);
      }
  }
  return test::result();
}
