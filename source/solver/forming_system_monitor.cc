// What the Newton solver reads about the contact set between iterations: did
// it change (its convergence test), and, for `Log iterations`, which pairs
// each tool closed and opened.
#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/solver/forming_system.h>

#include <sstream>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    bool FormingSystem<dim>::contact_set_changed()
    {
      const auto       &pairs = state.contact_set.pairs;
      std::vector<bool> active(pairs.size());
      // Locked pairs (chatter guard) do not count as changes.
      for (unsigned int k = 0; k < active.size(); ++k)
        active[k] = pairs[k].active || pairs[k].locked;
      const int changed = (active != last_active);
      last_active       = active;
      if (prm.nonlinear.log_iterations)
        count_changes();
      return Utilities::MPI::max(changed, state.comm) != 0;
    }

    template <int dim>
    void FormingSystem<dim>::count_changes()
    {
      // By record (node, tool), not by pair index: pairs enter and leave the
      // search distance between searches.
      const unsigned int n_tools = state.tools.size();
      std::vector<char>  status(state.contact_state.size(), 0);
      for (const auto &pair : state.contact_set.pairs)
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
    std::string FormingSystem<dim>::iteration_info() const
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
      if (use_dual && prm.nonlinear.log_iterations)
        s << "  rigid points: " << rigid_counts[0] << " (+" << rigid_counts[1]
          << "/-" << rigid_counts[2] << ")";
      if (holder_controlled())
        s << "  holder: w=" << w_accepted
          << " mm/s, F-F_set=" << -holder.residual() << " N";
      return s.str();
    }

#define INSTANTIATE(dim)                                          \
  template bool        FormingSystem<dim>::contact_set_changed(); \
  template void        FormingSystem<dim>::count_changes();       \
  template std::string FormingSystem<dim>::iteration_info() const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
