// Chooses the penalty factor eps_k of every contact pair. The assembler only
// reads the factors; strategies can be swapped without touching assembly.
#pragma once

#include <formsolve/contact/contact_set.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/tools/tool_set.h>

#include <memory>
#include <string>
#include <vector>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    class PenaltyEstimator
    {
    public:
      virtual ~PenaltyEstimator() = default;

      /// One factor per pair in @p set (N/mm: nodal force per mm of
      /// penetration).
      virtual void estimate(const ContactSet<dim>     &set,
                            const tools::ToolSet<dim> &tools,
                            std::vector<double>       &epsilon) = 0;

      virtual std::string name() const = 0;
    };

    /// eps_k = (tool penalty factor, N/mm^3) x (nodal area, mm^2).
    template <int dim>
    class FixedPenalty : public PenaltyEstimator<dim>
    {
    public:
      void        estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           std::vector<double>       &epsilon) override;
      std::string name() const override { return "fixed"; }
    };

    template <int dim>
    std::unique_ptr<PenaltyEstimator<dim>>
    create_penalty_estimator(const parameters::Contact &p);
  } // namespace contact
} // namespace formsolve
