// Chooses the penalty factor eps_k of every contact pair. The assembler only
// reads the factors; strategies can be swapped without touching assembly.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
    /// The current system without contact, for estimators that need it.
    struct SystemView
    {
      /// Body residual r_b (internal minus external forces, no contact), N.
      const dealii::TrilinosWrappers::MPI::Vector *residual = nullptr;
      /// Body tangent K_b = dr_b/dv (N s/mm), constrained rows included.
      const dealii::TrilinosWrappers::SparseMatrix *matrix      = nullptr;
      const dealii::AffineConstraints<double>      *constraints = nullptr;
      double                                        dt          = 0;
    };

    template <int dim>
    class PenaltyEstimator
    {
    public:
      virtual ~PenaltyEstimator() = default;

      /// Whether estimate() reads the SystemView (then the caller assembles
      /// the body system first).
      virtual bool needs_system() const { return false; }

      /// One factor per pair in @p set (N/mm: nodal force per mm of
      /// penetration).
      virtual void estimate(const ContactSet<dim>     &set,
                            const tools::ToolSet<dim> &tools,
                            const SystemView          &system,
                            std::vector<double>       &epsilon) = 0;

      /// Called once a step has converged with factors @p epsilon. Returns
      /// true if the step must be solved again (same on all ranks). May
      /// update the multipliers (ContactSet::shifts) of @p set.
      virtual bool finish_step(ContactSet<dim> & /*set*/,
                               const tools::ToolSet<dim> & /*tools*/,
                               const MPI_Comm /*comm*/)
      {
        return false;
      }

      /// Forget per-node state (the contact nodes changed: new mesh).
      virtual void reset() {}

      /// One line on the last estimate, for the iteration log.
      virtual std::string summary() const { return ""; }

      virtual std::string name() const = 0;
    };

    /// eps_k = (tool penalty factor, N/mm^3) x (nodal area, mm^2).
    template <int dim>
    class FixedPenalty : public PenaltyEstimator<dim>
    {
    public:
      void        estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           std::vector<double>       &epsilon) override;
      std::string name() const override { return "fixed"; }
    };

    /// The adaptive method (doc/theory.md, section 6; ../shared/method):
    /// eps_k = n_k . (r_b + K_b dv)_k / delta_k ("projection"), where dv moves
    /// every active node so that its predicted penetration is exactly delta
    /// and is zero elsewhere, or its limit dv -> 0, eps_k = n_k . r_b,k /
    /// delta_k ("force"); bounded relative to the node's tangent diagonal and
    /// damped to a factor per estimate. With
    /// @p strict, a converged step whose penetration exceeds delta anywhere is
    /// solved again with those nodes' factors scaled by penetration/delta.
    template <int dim>
    class AdaptivePenalty : public PenaltyEstimator<dim>
    {
    public:
      AdaptivePenalty(const parameters::Contact &p, const bool strict);

      bool        needs_system() const override { return true; }
      void        estimate(const ContactSet<dim>     &set,
                           const tools::ToolSet<dim> &tools,
                           const SystemView          &system,
                           std::vector<double>       &epsilon) override;
      bool        finish_step(ContactSet<dim>           &set,
                              const tools::ToolSet<dim> &tools,
                              const MPI_Comm             comm) override;
      std::string summary() const override;
      void        reset() override
      {
        last_active.clear();
        last_epsilon.clear();
        scale.clear();
        previous.clear();
      }
      std::string name() const override
      {
        return strict ? "adaptive-strict" : "adaptive";
      }

      /// Range of the last factors over the active pairs of this rank (N/mm),
      /// and the largest eps_k dt / K_kk.
      double       min_factor = 0, max_factor = 0, max_ratio = 0;
      unsigned int n_active = 0;

    private:
      double              lower, upper;
      bool                freeze, strict;
      std::vector<bool>   last_active;
      std::vector<double> last_epsilon;
      /// adaptive-strict: persistent scaling per (node, tool).
      std::vector<double> scale;
      /// Last factor per (node, tool), kept across iterations and steps.
      std::vector<double> previous;
      bool                projection; // the published estimate with K_b dv
      double              damping;    // max change factor per estimate
      double              target;     // aim at this fraction of delta
    };

    /// Augmented Lagrangian (Uzawa) on the factors of an inner strategy
    /// (fixed or adaptive): the force of pair k is eps_k <s_k - g_k> with the
    /// gap shift s_k = lambda_k / eps_k. After a converged step every pair
    /// gets s_k <- max(0, s_k - g_k), i.e. lambda_k <- <lambda_k - eps_k g_k>,
    /// and the step is solved again while a node is deeper than delta.
    template <int dim>
    class AugmentedLagrangian : public PenaltyEstimator<dim>
    {
    public:
      explicit AugmentedLagrangian(
        std::unique_ptr<PenaltyEstimator<dim>> inner);

      bool needs_system() const override { return inner->needs_system(); }
      void estimate(const ContactSet<dim>     &set,
                    const tools::ToolSet<dim> &tools,
                    const SystemView          &system,
                    std::vector<double>       &epsilon) override
      {
        inner->estimate(set, tools, system, epsilon);
      }
      bool        finish_step(ContactSet<dim>           &set,
                              const tools::ToolSet<dim> &tools,
                              const MPI_Comm             comm) override;
      std::string summary() const override { return inner->summary(); }
      void        reset() override { inner->reset(); }
      std::string name() const override
      {
        return "augmented-lagrangian (" + inner->name() + ")";
      }

    private:
      std::unique_ptr<PenaltyEstimator<dim>> inner;
    };

    template <int dim>
    std::unique_ptr<PenaltyEstimator<dim>>
    create_penalty_estimator(const parameters::Contact &p);
  } // namespace contact
} // namespace formsolve
