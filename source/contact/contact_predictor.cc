#include <deal.II/base/exceptions.h>

#include <formsolve/contact/contact_predictor.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    unsigned int keep_contact(const ContactSet<dim>                 &set,
                              const ContactState                    &state,
                              const tools::ToolSet<dim>             &tools,
                              const double                           dt,
                              dealii::TrilinosWrappers::MPI::Vector &change)
    {
      Assert(dt > 0, dealii::ExcInternalError());
      unsigned int moved = 0;
      for (const auto &pair : set.pairs)
        {
          // Only surface that faces the tool can touch it (as in the search).
          if (!state(pair.node, pair.tool).active || pair.active ||
              pair.area <= 0)
            continue;
          // predicted_gap = gap + n.(v - v_tool) dt is linear in v: this
          // normal velocity change brings it just below the shift.
          const double target =
            pair.shift - touch_depth * tools.allowed_penetration(pair.tool);
          const double dv_n = (target - pair.predicted_gap) / dt;
          for (unsigned int a = 0; a < dim; ++a)
            change[set.nodes[pair.node].dofs[a]] += dv_n * pair.normal[a];
          ++moved;
        }
      return moved;
    }

#define INSTANTIATE(dim)                                          \
  template unsigned int keep_contact(const ContactSet<dim> &,     \
                                     const ContactState &,        \
                                     const tools::ToolSet<dim> &, \
                                     const double,                \
                                     dealii::TrilinosWrappers::MPI::Vector &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace contact
} // namespace formsolve
