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
      void        estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           ContactState              &state,
                           std::vector<double>       &epsilon) override;
      std::string name() const override { return "fixed"; }
    };
  } // namespace contact
} // namespace formsolve
