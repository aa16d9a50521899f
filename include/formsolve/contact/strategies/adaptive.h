// The adaptive method (doc/theory.md, section 6; ../shared/method):
// eps_k = n_k . (r_b + K_b dv)_k / delta_k ("projection"), where dv moves
// every active node so that its predicted penetration is exactly delta and is
// zero elsewhere, or its limit dv -> 0, eps_k = n_k . r_b,k / delta_k
// ("force"); bounded relative to the node's tangent diagonal and damped to a
// factor per estimate. With @p strict (adaptive-strict), a converged step
// whose penetration exceeds delta anywhere is solved again with those nodes'
// factors scaled by penetration/delta.
#pragma once

#include <formsolve/contact/penalty_strategy.h>

#include <algorithm>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    class AdaptivePenalty : public PenaltyStrategy<dim>
    {
    public:
      AdaptivePenalty(const parameters::Contact &p, const bool strict);

      void begin_solve() override
      {
        last_epsilon.clear();
        held = false;
      }
      void at_point(const ContactSet<dim>     &set,
                    const tools::ToolSet<dim> &tools,
                    const SystemView          &system,
                    ContactState              &state,
                    std::vector<double>       &epsilon,
                    const bool                 same_pairs) override;
      bool at_iterate(const ContactSet<dim>     &set,
                      const tools::ToolSet<dim> &tools,
                      const SystemView          &system,
                      ContactState              &state,
                      std::vector<double>       &epsilon) override;
      /// The factors of every pair in @p set at the iterate of @p system
      /// (unconditionally; within the strategy's rules of holding and
      /// freezing).
      void        estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           ContactState              &state,
                           std::vector<double>       &epsilon);
      void        converged(const ContactSet<dim>     &set,
                            const tools::ToolSet<dim> &tools,
                            const SystemView          &system,
                            ContactState              &state) override;
      bool        finish_solve(const ContactSet<dim>     &set,
                               const tools::ToolSet<dim> &tools,
                               ContactState              &state,
                               const MPI_Comm             comm) override;
      bool        tighten(const ContactSet<dim>     &set,
                          const tools::ToolSet<dim> &tools,
                          ContactState              &state,
                          const MPI_Comm             comm) override;
      std::string summary() const override;
      std::string name() const override
      {
        return strict ? "adaptive-strict" : "adaptive";
      }

      /// Range of the last factors over the active pairs (N/mm), and the
      /// largest eps_k dt / K_kk.
      double       min_factor = 0, max_factor = 0, max_ratio = 0;
      unsigned int n_active = 0;

    private:
      /// Whether estimate() at @p set would return the factors of its last
      /// call without reading the system (factors held or frozen); the same
      /// on all ranks of @p comm.
      bool holds(const ContactSet<dim>     &set,
                 const tools::ToolSet<dim> &tools,
                 const ContactState        &state,
                 const bool                 predictor,
                 const MPI_Comm             comm) const;
      /// Smallest and largest factor, largest factor/stiffness ratio and
      /// the count of the active pairs, over all ranks.
      void record_statistics(const std::vector<bool>   &active,
                             const std::vector<double> &epsilon,
                             const std::vector<double> &stiffness_of,
                             const MPI_Comm             comm);
      /// The damped estimate of every pair at the iterate of @p system
      /// (writes nothing), and the pairs' normal stiffness (N/mm).
      void estimate_at(const ContactSet<dim>     &set,
                       const tools::ToolSet<dim> &tools,
                       const SystemView          &system,
                       const ContactState        &state,
                       std::vector<double>       &eps,
                       std::vector<double>       &stiffness) const;
      /// per_step: the estimate at @p system's iterate into the records of
      /// the active pairs.
      void record_estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           ContactState              &state) const;
      /// Pair @p k's last factor, or the tool's fixed penalty for a new one.
      double start_factor(const ContactSet<dim>     &set,
                          const tools::ToolSet<dim> &tools,
                          const ContactState        &state,
                          const unsigned int         k) const;
      double bounded(const double eps, const double stiffness) const
      {
        return std::clamp(eps, lower * stiffness, upper * stiffness);
      }
      /// The strict check: scale up the nodes deeper than delta; with
      /// @p relax also scale back those well inside it. True if any was
      /// deeper (on any rank).
      bool   check_bound(const ContactSet<dim>     &set,
                         const tools::ToolSet<dim> &tools,
                         ContactState              &state,
                         const MPI_Comm             comm,
                         const bool                 relax) const;
      double lower, upper;
      bool   freeze, per_step, hold_predictor, strict;
      bool   refresh = false; // per_step: estimate at the next iterate
      bool   held    = false; // per_step: this solve's factors are set
      bool   projection;      // the published estimate with K_b dv
      double damping;         // max change factor per estimate
      double target;          // aim at this fraction of delta
      /// Within one solve: the pairs' status and factors of the last
      /// estimate (factors are frozen once the status repeats).
      std::vector<char>   last_status; // 0 open, 1 active, 2 locked
      std::vector<double> last_epsilon, last_stiffness;
    };
  } // namespace contact
} // namespace formsolve
