#include <deal.II/base/exceptions.h>

#include <formsolve/contact/contact_state.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace contact
  {
    void ContactState::begin_solve()
    {
      for (auto &r : records)
        {
          r.flips  = 0;
          r.locked = false;
        }
      baseline = true;
    }

    template <int dim>
    void ContactState::track_status(ContactSet<dim>   &set,
                                    const unsigned int max_flips)
    {
      Assert(records.size() == set.nodes.size() * tools,
             dealii::ExcInternalError());
      // The first search of a solve sets the status the changes count from.
      if (baseline)
        {
          for (auto &r : records)
            r.active = false;
          for (auto &pair : set.pairs)
            (*this)(pair.node, pair.tool).active = pair.active;
          baseline = false;
          return;
        }
      for (auto &pair : set.pairs)
        {
          auto &r = (*this)(pair.node, pair.tool);
          if (!r.locked && pair.active != r.active && ++r.flips >= max_flips)
            r.locked = true;
          pair.locked = r.locked;
          r.active    = pair.active;
        }
    }

#define INSTANTIATE(dim)                                      \
  template void ContactState::track_status(ContactSet<dim> &, \
                                           const unsigned int);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace contact
} // namespace formsolve
