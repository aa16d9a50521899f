#include <deal.II/base/mpi.h>

#include <formsolve/contact/contact_assembly.h>
#include <formsolve/contact/contact_predictor.h>
#include <formsolve/forming/contact_operator.h>
#include <formsolve/model/dimensions.h>

#include <sstream>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    ContactOperator<dim>::ContactOperator(
      const parameters::Run         &prm,
      state::State<dim>             &state,
      contact::PenaltyStrategy<dim> &strategy,
      TimerOutput                   &timer)
        : prm(prm)
        , state(state)
        , strategy(strategy)
        , timer(timer)
        , search_(prm.contact.search_distance)
    {}

    template <int dim>
    void ContactOperator<dim>::reinit()
    {
      epsilon.clear();
      keys.clear();
      last_active.clear();
      last_record_status.clear(); // new surface nodes
    }

    template <int dim>
    void ContactOperator<dim>::begin_solve()
    {
      sync_nodes();
      state.contact_state.begin_solve();
      strategy.begin_solve();
    }

    template <int dim>
    void ContactOperator<dim>::find_pairs(
      const VectorType                  &v,
      const std::vector<Tensor<1, dim>> &tool_velocities,
      const double                       dt)
    {
      search_.evaluate(state.tools,
                       tool_velocities,
                       state.displacement_ghost,
                       v,
                       dt,
                       state.contact_state,
                       set);
    }

    template <int dim>
    void ContactOperator<dim>::search(
      const VectorType                  &v,
      const std::vector<Tensor<1, dim>> &tool_velocities,
      const double                       dt)
    {
      TimerOutput::Scope t(timer, "contact");
      find_pairs(v, tool_velocities, dt);
      state.contact_state.track_status(set, prm.contact.max_status_flips);
    }

    template <int dim>
    void ContactOperator<dim>::predict(VectorType  &v,
                                       VectorType  &ghost,
                                       const double dt)
    {
      TimerOutput::Scope t(timer, "contact");
      sync_nodes();
      // No status tracking: the status of the previous solve is what
      // keep_contact() reads.
      ghost = v;
      find_pairs(ghost, state.tools.velocities(), dt);
      VectorType change(state.owned, state.comm);
      contact::keep_contact(set, state.contact_state, state.tools, dt, change);
      change.compress(VectorOperation::add);
      v += change;
      state.constraints.distribute(v);
    }

    template <int dim>
    void ContactOperator<dim>::sync_nodes()
    {
      // The nodes and their areas are the state's (set up with the mesh,
      // areas updated with the configuration once a step).
      set.nodes = state.contact_set.nodes;
    }

    template <int dim>
    void ContactOperator<dim>::accept()
    {
      state.contact_set.pairs = set.pairs;
    }

    template <int dim>
    std::vector<double> ContactOperator<dim>::accepted_factors() const
    {
      const auto &accepted = state.contact_set.pairs;
      bool        match    = factors_match() && accepted.size() == keys.size();
      for (unsigned int k = 0; match && k < accepted.size(); ++k)
        match = keys[k].first == accepted[k].node &&
                keys[k].second == accepted[k].tool;
      return match ? epsilon : std::vector<double>(accepted.size(), 0.);
    }

    template <int dim>
    bool ContactOperator<dim>::factors_match() const
    {
      const auto &pairs = set.pairs;
      if (keys.size() != pairs.size() || epsilon.size() != pairs.size())
        return false;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (keys[k].first != pairs[k].node || keys[k].second != pairs[k].tool)
          return false;
      return true;
    }

    template <int dim>
    void ContactOperator<dim>::keep_keys()
    {
      const auto &pairs = set.pairs;
      AssertDimension(epsilon.size(), pairs.size());
      keys.resize(pairs.size());
      for (unsigned int k = 0; k < pairs.size(); ++k)
        keys[k] = {pairs[k].node, pairs[k].tool};
    }

    template <int dim>
    void ContactOperator<dim>::at_point(const contact::SystemView &system)
    {
      TimerOutput::Scope t(timer, estimate_section);
      // Collective: decide on all ranks alike.
      const bool same =
        Utilities::MPI::min(int(factors_match()), state.comm) != 0;
      strategy
        .at_point(set, state.tools, system, state.contact_state, epsilon, same);
      keep_keys();
    }

    template <int dim>
    bool ContactOperator<dim>::at_iterate(const contact::SystemView &system)
    {
      TimerOutput::Scope t(timer, estimate_section);
      Assert(factors_match(), ExcInternalError());
      return strategy.at_iterate(set,
                                 state.tools,
                                 system,
                                 state.contact_state,
                                 epsilon);
    }

    template <int dim>
    bool ContactOperator<dim>::tighten()
    {
      if (!strategy.tighten(set, state.tools, state.contact_state, state.comm))
        return false;
      // Estimate again with the new scales at this iterate.
      strategy.begin_solve();
      return true;
    }

    template <int dim>
    void ContactOperator<dim>::converged(const contact::SystemView &system)
    {
      TimerOutput::Scope t(timer, estimate_section);
      strategy.converged(set, state.tools, system, state.contact_state);
    }

    template <int dim>
    void ContactOperator<dim>::add(MatrixType  *matrix,
                                   VectorType  *residual,
                                   const double dt,
                                   const bool   newton) const
    {
      TimerOutput::Scope t(timer, "assembly: contact terms");
      contact::add_contact_terms(set,
                                 factors(),
                                 state.tools,
                                 prm.contact.regularisation_velocity,
                                 dt,
                                 newton,
                                 state.constraints,
                                 matrix,
                                 residual);
    }

    template <int dim>
    bool ContactOperator<dim>::changed()
    {
      const auto       &pairs = set.pairs;
      std::vector<bool> active(pairs.size());
      for (unsigned int k = 0; k < active.size(); ++k)
        active[k] = pairs[k].active || pairs[k].locked;
      const int changed = (active != last_active);
      last_active       = active;
      if (prm.nonlinear.log_iterations)
        count_changes();
      return Utilities::MPI::max(changed, state.comm) != 0;
    }

    template <int dim>
    void ContactOperator<dim>::count_changes()
    {
      // By record (node, tool), not by pair index: pairs enter and leave the
      // search distance between searches.
      const unsigned int n_tools = state.tools.size();
      std::vector<char>  status(state.contact_state.size(), 0);
      for (const auto &pair : set.pairs)
        status[pair.node * n_tools + pair.tool] = pair.active || pair.locked;
      closed.assign(n_tools, 0);
      opened.assign(n_tools, 0);
      if (last_record_status.size() == status.size())
        for (unsigned int i = 0; i < status.size(); ++i)
          if (status[i] != last_record_status[i])
            ++(status[i] ? closed : opened)[i % n_tools];
      last_record_status = status;
      for (auto *counts : {&closed, &opened})
        {
          const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                         counts->data(),
                                         n_tools,
                                         MPI_UNSIGNED,
                                         MPI_SUM,
                                         state.comm);
          AssertThrowMPI(ierr);
        }
    }

    template <int dim>
    std::string ContactOperator<dim>::info() const
    {
      std::ostringstream s;
      s << strategy.summary();
      // Pairs closed (+) and opened (-) per tool since the last search.
      std::string changes;
      for (unsigned int t = 0; t < closed.size(); ++t)
        if (closed[t] + opened[t] > 0)
          changes += (changes.empty() ? "" : ", ") + state.tools.key(t) + " +" +
                     std::to_string(closed[t]) + "/-" +
                     std::to_string(opened[t]);
      if (!changes.empty())
        s << "  pairs: " << changes;
      return s.str();
    }

#define INSTANTIATE(dim) template class ContactOperator<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
