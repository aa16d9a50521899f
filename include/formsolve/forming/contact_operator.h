// Contact of the sheet with the rigid tools as one operator of the step
// (doc/theory.md, section 6): the pairs at a trial velocity, the penalty
// factors from the body system, and the contact forces and stiffness added
// to the system. It owns the pairs of the point evaluated last (the state's
// contact set gets those of the accepted iterate), the search, the
// strategy's factors and what changed between iterates, and works on the
// state's contact state, which refinement transfers and checkpoints save.
#pragma once

#include <deal.II/base/timer.h>

#include <formsolve/contact/contact_search.h>
#include <formsolve/contact/penalty_strategy.h>
#include <formsolve/forming/assembler.h>
#include <formsolve/state/state.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class ContactOperator
    {
    public:
      /// The timer section of the strategies' estimates.
      static constexpr const char *estimate_section = "penalty estimate";

      ContactOperator(const parameters::Run         &prm,
                      state::State<dim>             &state,
                      contact::PenaltyStrategy<dim> &strategy,
                      dealii::TimerOutput           &timer);

      /// A new mesh: no factors, no memory of the last search.
      void reinit();
      /// A Newton solve of a step begins.
      void begin_solve();

      /// The pairs at the ghosted velocity @p v with the tools at
      /// @p tool_velocities (one per tool), for a step of @p dt; their
      /// status enters the contact state.
      void search(const VectorType                          &v,
                  const std::vector<dealii::Tensor<1, dim>> &tool_velocities,
                  const double                               dt);
      /// The step's predictor @p v corrected where it would lift nodes in
      /// contact off their tools (Nonlinear solver/Predictor = keep
      /// contact); @p ghost: a ghosted vector to search with.
      void predict(VectorType &v, VectorType &ghost, const double dt);

      /// A point was evaluated and searched: factors for its pairs (the
      /// strategy reads @p system only if it needs to).
      void at_point(const contact::SystemView &system);
      /// Newton accepted the point: whether its factors were estimated anew
      /// (collective).
      bool at_iterate(const contact::SystemView &system);
      /// The strategy's bound near convergence: whether it tightened the
      /// factors (collective); if so, the next estimate is not frozen.
      bool tighten();
      /// The solve converged: the strategy sees the body system.
      void converged(const contact::SystemView &system);

      /// Contact forces and stiffness of the pairs with their factors into
      /// what is given (either may be null).
      void add(MatrixType  *matrix,
               VectorType  *residual,
               const double dt,
               const bool   newton) const;

      /// Whether the set of active pairs changed since the last call
      /// (collective); locked pairs (chatter guard) count as active.
      bool changed();

      /// Newton accepted the point: its pairs become the state's.
      void accept();
      /// One factor per pair of the state's (accepted) pairs; zeros if they
      /// have none (before the first solve).
      std::vector<double> accepted_factors() const;
      /// The pairs of the point evaluated last (nodes: the state's).
      const contact::ContactSet<dim> &pairs() const { return set; }
      /// One per pair of the last search, in its order.
      const std::vector<double> &factors() const
      {
        Assert(factors_match(), dealii::ExcInternalError());
        return epsilon;
      }
      /// For the iteration log: the strategy's summary and the pairs each
      /// tool closed and opened since the last call of changed().
      std::string info() const;

    private:
      /// Whether the factors are those of the current pairs, pair by pair
      /// (node and tool); on this rank.
      bool factors_match() const;
      /// The factors' pairs become the current ones.
      void keep_keys();
      /// The state's nodes (and areas) into the point's set.
      void sync_nodes();
      void
      find_pairs(const VectorType                          &v,
                 const std::vector<dealii::Tensor<1, dim>> &tool_velocities,
                 const double                               dt);
      /// The pairs each tool closed and opened since the last call (log).
      void count_changes();

      const parameters::Run         &prm;
      state::State<dim>             &state;
      contact::PenaltyStrategy<dim> &strategy;
      dealii::TimerOutput           &timer;
      contact::ContactSearch<dim>    search_;
      /// The pairs of the point evaluated last; the state holds those of
      /// the accepted iterate.
      contact::ContactSet<dim> set;
      std::vector<double>      epsilon;
      /// (node, tool) of each factor.
      std::vector<std::pair<unsigned int, unsigned int>> keys;
      std::vector<bool>                                  last_active;
      std::vector<char>                                  last_record_status;
      std::vector<unsigned int>                          closed, opened;
    };
  } // namespace solver
} // namespace formsolve
