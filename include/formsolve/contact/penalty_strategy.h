// Chooses the penalty factor eps_k of every contact pair. The assembler only
// reads the factors; a strategy reads the contact set and the body system
// and writes only the contact state. Each strategy lives in its own file
// under contact/strategies/ and registers itself by name.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/contact/contact_state.h>
#include <formsolve/parameters/contact.h>
#include <formsolve/tools/tool_set.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace formsolve
{
  namespace contact
  {
    /// The current system without contact, for strategies that need it.
    struct SystemView
    {
      /// Body residual r_b (internal minus external forces, no contact), N.
      const dealii::TrilinosWrappers::MPI::Vector *residual = nullptr;
      /// Body tangent K_b = dr_b/dv (N s/mm), constrained rows included.
      const dealii::TrilinosWrappers::SparseMatrix *matrix      = nullptr;
      const dealii::AffineConstraints<double>      *constraints = nullptr;
      double                                        dt          = 0;
      /// The iterate is a step's predictor (the previous velocity in the new
      /// configuration), not yet a Newton iterate. The same on all ranks.
      bool predictor = false;
    };

    template <int dim>
    class PenaltyStrategy
    {
    public:
      virtual ~PenaltyStrategy() = default;

      /// Whether estimate() reads the SystemView (then the caller assembles
      /// the body system first).
      virtual bool needs_system() const { return false; }

      /// A new Newton solve of a step begins.
      virtual void begin_solve() {}

      /// One factor per pair in @p set (N/mm: nodal force per mm of
      /// penetration). May update the per-node memory in @p state.
      virtual void estimate(const ContactSet<dim>     &set,
                            const tools::ToolSet<dim> &tools,
                            const SystemView          &system,
                            ContactState              &state,
                            std::vector<double>       &epsilon) = 0;

      /// Whether estimate() at @p set would return the factors of its last
      /// call without reading the system (factors held or frozen); the same
      /// on all ranks of @p comm. Then an iterate whose tangent was not
      /// assembled needs none for the estimate.
      virtual bool holds_factors(const ContactSet<dim> & /*set*/,
                                 const tools::ToolSet<dim> & /*tools*/,
                                 const ContactState & /*state*/,
                                 const bool /*predictor*/,
                                 const MPI_Comm /*comm*/) const
      {
        return !needs_system();
      }

      /// Whether converged() reads the system.
      virtual bool reads_converged_system() const { return false; }

      /// Called once a solve has converged, with the body system at the
      /// converged iterate, before finish_solve(): a strategy that holds its
      /// factors within solves estimates the next solve's here.
      virtual void converged(const ContactSet<dim> & /*set*/,
                             const tools::ToolSet<dim> & /*tools*/,
                             const SystemView & /*system*/,
                             ContactState & /*state*/)
      {}

      /// Called once a solve has converged. Returns true if the step must be
      /// solved again (same on all ranks); may then update @p state (strict
      /// scales, multipliers) for that solve.
      virtual bool finish_solve(const ContactSet<dim> & /*set*/,
                                const tools::ToolSet<dim> & /*tools*/,
                                ContactState & /*state*/,
                                const MPI_Comm /*comm*/)
      {
        return false;
      }

      /// Within a solve, near convergence: tighten the factors of the nodes
      /// deeper than allowed (strict scales; nothing is relaxed). Returns
      /// true if any changed (same on all ranks).
      virtual bool tighten(const ContactSet<dim> & /*set*/,
                           const tools::ToolSet<dim> & /*tools*/,
                           ContactState & /*state*/,
                           const MPI_Comm /*comm*/)
      {
        return false;
      }
      /// One line on the last estimate, for the iteration log.
      virtual std::string summary() const { return ""; }

      virtual std::string name() const = 0;
    };

    template <int dim>
    using StrategyFactory = std::function<std::unique_ptr<PenaltyStrategy<dim>>(
      const parameters::Contact &)>;

    /// Registers a strategy for both dimensions; returns true (for a static
    /// initialiser in the strategy's file).
    bool register_penalty_strategy(const std::string        &name,
                                   const StrategyFactory<2> &factory2,
                                   const StrategyFactory<3> &factory3);

    /// The registered names, "a|b|...", for Patterns::Selection.
    std::string penalty_strategy_names();

    /// The strategy named by Contact/Penalty strategy.
    template <int dim>
    std::unique_ptr<PenaltyStrategy<dim>>
    create_penalty_strategy(const parameters::Contact &p);
  } // namespace contact
} // namespace formsolve
