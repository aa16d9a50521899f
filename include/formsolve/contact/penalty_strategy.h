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
    /// The body system (no contact) at the point the factors are for. A view
    /// made with @p prepare assembles the point's tangent when first read:
    /// a strategy that does not read it costs no assembly. That first read
    /// is collective: a strategy reads on every rank (with pairs or
    /// without) or on none.
    class SystemView
    {
    public:
      SystemView(const dealii::TrilinosWrappers::MPI::Vector  *residual,
                 const dealii::TrilinosWrappers::SparseMatrix *matrix,
                 const dealii::AffineConstraints<double>      *constraints,
                 const double                                  dt,
                 const bool            predictor = false,
                 std::function<void()> prepare   = {})
          : dt(dt)
          , predictor(predictor)
          , r_b(residual)
          , K_b(matrix)
          , constraints_(constraints)
          , prepare(std::move(prepare))
      {}
      /// Body residual r_b (internal minus external forces, no contact), N.
      const dealii::TrilinosWrappers::MPI::Vector &residual() const
      {
        ready();
        return *r_b;
      }
      /// Body tangent K_b = dr_b/dv (N s/mm), constrained rows included.
      const dealii::TrilinosWrappers::SparseMatrix &matrix() const
      {
        ready();
        return *K_b;
      }
      const dealii::AffineConstraints<double> &constraints() const
      {
        return *constraints_;
      }
      /// Reads nothing of the system.
      MPI_Comm comm() const { return r_b->get_mpi_communicator(); }

      const double dt;
      /// The iterate is a step's predictor (the previous velocity in the new
      /// configuration), not yet a Newton iterate. The same on all ranks.
      const bool predictor;

    private:
      /// Collective: a strategy reads the system on all ranks or on none.
      void ready() const
      {
        if (prepare)
          {
            const auto p = std::move(prepare);
            prepare      = nullptr;
            p();
          }
      }
      const dealii::TrilinosWrappers::MPI::Vector  *r_b;
      const dealii::TrilinosWrappers::SparseMatrix *K_b;
      const dealii::AffineConstraints<double>      *constraints_;
      mutable std::function<void()>                 prepare;
    };

    template <int dim>
    class PenaltyStrategy
    {
    public:
      virtual ~PenaltyStrategy() = default;

      /// A new Newton solve of a step begins.
      virtual void begin_solve() {}

      /// A point was evaluated (a line-search trial or an iterate) and its
      /// pairs found: @p epsilon gets one factor per pair in @p set (N/mm:
      /// nodal force per mm of penetration). @p same_pairs: @p epsilon holds
      /// factors of these pairs (same nodes and tools) from an earlier point.
      virtual void at_point(const ContactSet<dim>     &set,
                            const tools::ToolSet<dim> &tools,
                            const SystemView          &system,
                            ContactState              &state,
                            std::vector<double>       &epsilon,
                            const bool                 same_pairs) = 0;

      /// Newton accepted the point: new factors from its body system, if the
      /// strategy estimates per iterate. Returns whether @p epsilon was
      /// estimated anew (the same on all ranks).
      virtual bool at_iterate(const ContactSet<dim> & /*set*/,
                              const tools::ToolSet<dim> & /*tools*/,
                              const SystemView & /*system*/,
                              ContactState & /*state*/,
                              std::vector<double> & /*epsilon*/)
      {
        return false;
      }

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
