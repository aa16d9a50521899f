#include <formsolve/contact/strategies/augmented_lagrangian.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    AugmentedLagrangian<dim>::AugmentedLagrangian(
      std::unique_ptr<PenaltyStrategy<dim>> inner)
        : inner(std::move(inner))
    {}

    template <int dim>
    bool
    AugmentedLagrangian<dim>::finish_solve(const ContactSet<dim>     &set,
                                           const tools::ToolSet<dim> &tools,
                                           ContactState              &state,
                                           const MPI_Comm             comm)
    {
      inner->finish_solve(set, tools, state, comm);
      // Pairs out of the search distance lose their multiplier.
      for (unsigned int node = 0; node < set.nodes.size(); ++node)
        for (unsigned int t = 0; t < tools.size(); ++t)
          state(node, t).shift = 0;
      int again = 0;
      for (const auto &pair : set.pairs)
        {
          // Uzawa: lambda <- <lambda - eps g>, as a shift with eps fixed.
          state(pair.node, pair.tool).shift =
            std::max(0., pair.shift - pair.predicted_gap);
          if (pair.active &&
              -pair.predicted_gap > tools.allowed_penetration(pair.tool))
            again = 1;
        }
      return Utilities::MPI::max(again, comm) != 0;
    }

#define INSTANTIATE(dim) template class AugmentedLagrangian<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE

    namespace
    {
      template <int dim>
      std::unique_ptr<PenaltyStrategy<dim>> create(const parameters::Contact &p)
      {
        AssertThrow(p.max_strict_passes > 0,
                    dealii::ExcMessage(
                      "Parameter Contact/Max strict passes: must be at least "
                      "1 for augmented-lagrangian (its Uzawa updates are the "
                      "passes)"));
        parameters::Contact inner = p;
        inner.penalty_strategy    = p.al_penalty;
        return std::make_unique<AugmentedLagrangian<dim>>(
          create_penalty_strategy<dim>(inner));
      }
      [[maybe_unused]] const bool registered_augmented_lagrangian =
        register_penalty_strategy("augmented-lagrangian", create<2>, create<3>);
    } // namespace
  }   // namespace contact
} // namespace formsolve
