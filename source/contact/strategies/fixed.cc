#include <formsolve/contact/strategies/fixed.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    void FixedPenalty<dim>::at_point(const ContactSet<dim>     &set,
                                     const tools::ToolSet<dim> &tools,
                                     const SystemView &,
                                     ContactState &,
                                     std::vector<double> &epsilon,
                                     const bool)
    {
      epsilon.resize(set.pairs.size());
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        epsilon[k] =
          tools.penalty_factor(set.pairs[k].tool) * set.pairs[k].area;
    }

#define INSTANTIATE(dim) template class FixedPenalty<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE

    namespace
    {
      [[maybe_unused]] const bool registered_fixed = register_penalty_strategy(
        "fixed",
        [](const parameters::Contact &) {
          return std::make_unique<FixedPenalty<2>>();
        },
        [](const parameters::Contact &) {
          return std::make_unique<FixedPenalty<3>>();
        });
    } // namespace
  }   // namespace contact
} // namespace formsolve
