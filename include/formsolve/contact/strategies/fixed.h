// Fixed penalty: eps_k = (tool penalty factor, N/mm^3) x (nodal area, mm^2).
#pragma once

#include <formsolve/contact/penalty_strategy.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    class FixedPenalty : public PenaltyStrategy<dim>
    {
    public:
      /// At every point: the factors follow from the pairs alone.
      void        at_point(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           ContactState              &state,
                           std::vector<double>       &epsilon,
                           const bool                 same_pairs) override;
      std::string name() const override { return "fixed"; }
    };
  } // namespace contact
} // namespace formsolve
