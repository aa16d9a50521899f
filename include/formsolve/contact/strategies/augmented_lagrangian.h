// Augmented Lagrangian (Uzawa) on the factors of an inner strategy (fixed or
// adaptive): the force of pair k is eps_k <s_k - g_k> with the gap shift
// s_k = lambda_k / eps_k kept in the contact state. After a converged solve
// every pair gets s_k <- max(0, s_k - g_k), i.e. lambda_k <- <lambda_k -
// eps_k g_k>, and the step is solved again while a node is deeper than delta.
#pragma once

#include <formsolve/contact/penalty_strategy.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    class AugmentedLagrangian : public PenaltyStrategy<dim>
    {
    public:
      explicit AugmentedLagrangian(std::unique_ptr<PenaltyStrategy<dim>> inner);

      void begin_solve() override { inner->begin_solve(); }
      void at_point(const ContactSet<dim>     &set,
                    const tools::ToolSet<dim> &tools,
                    const SystemView          &system,
                    ContactState              &state,
                    std::vector<double>       &epsilon,
                    const bool                 same_pairs) override
      {
        inner->at_point(set, tools, system, state, epsilon, same_pairs);
      }
      bool at_iterate(const ContactSet<dim>     &set,
                      const tools::ToolSet<dim> &tools,
                      const SystemView          &system,
                      ContactState              &state,
                      std::vector<double>       &epsilon) override
      {
        return inner->at_iterate(set, tools, system, state, epsilon);
      }
      void converged(const ContactSet<dim>     &set,
                     const tools::ToolSet<dim> &tools,
                     const SystemView          &system,
                     ContactState              &state) override
      {
        inner->converged(set, tools, system, state);
      }
      bool        finish_solve(const ContactSet<dim>     &set,
                               const tools::ToolSet<dim> &tools,
                               ContactState              &state,
                               const MPI_Comm             comm) override;
      std::string summary() const override { return inner->summary(); }
      std::string name() const override
      {
        return "augmented-lagrangian (" + inner->name() + ")";
      }

    private:
      std::unique_ptr<PenaltyStrategy<dim>> inner;
    };
  } // namespace contact
} // namespace formsolve
