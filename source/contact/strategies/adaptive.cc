#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/contact/strategies/adaptive.h>
#include <formsolve/model/dimensions.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    namespace
    {
      /// Status of every pair for the freeze: a pair locked by the chatter
      /// guard counts as unchanged whatever it does, as in Newton's
      /// convergence test.
      template <int dim>
      std::vector<char> freeze_status(const ContactSet<dim> &set)
      {
        std::vector<char> status(set.pairs.size());
        for (unsigned int k = 0; k < status.size(); ++k)
          status[k] = set.pairs[k].locked ? 2 : char(set.pairs[k].active);
        return status;
      }

      /// Whether @p dof hangs (a constraint with masters; not a Dirichlet or
      /// symmetry line).
      bool hanging(const AffineConstraints<double> &c,
                   const types::global_dof_index    dof)
      {
        const auto *entries = c.get_constraint_entries(dof);
        return entries != nullptr && !entries->empty();
      }

      /// At hanging nodes the body residual has no entry (condensed into the
      /// masters), so their estimate sees no force and would sink to the
      /// lower bound: there the factor per area (N/mm^3) is interpolated
      /// from the masters' active pairs, as any constrained field.
      template <int dim>
      void interpolate_hanging(const ContactSet<dim>               &set,
                               const AffineConstraints<double>     &constraints,
                               const TrilinosWrappers::MPI::Vector &layout,
                               std::vector<bool>                   &is_hanging,
                               std::vector<double>                 &epsilon)
      {
        const unsigned int n = set.pairs.size();
        is_hanging.assign(n, false);
        for (unsigned int k = 0; k < n; ++k)
          is_hanging[k] =
            hanging(constraints, set.nodes[set.pairs[k].node].dofs[dim - 1]);
        const MPI_Comm comm = layout.get_mpi_communicator();
        if (Utilities::MPI::max(
              int(std::count(is_hanging.begin(), is_hanging.end(), true)),
              comm) == 0)
          return;
        // Factor per area of the active, not hanging pairs at their nodes.
        TrilinosWrappers::MPI::Vector per_area(layout);
        per_area = 0;
        for (unsigned int k = 0; k < n; ++k)
          {
            const auto &pair = set.pairs[k];
            if (pair.active && !is_hanging[k] && pair.area > 0)
              per_area[set.nodes[pair.node].dofs[dim - 1]] =
                std::max(double(per_area[set.nodes[pair.node].dofs[dim - 1]]),
                         epsilon[k] / pair.area);
          }
        per_area.compress(VectorOperation::insert);
        TrilinosWrappers::MPI::Vector ghosted(layout.locally_owned_elements(),
                                              constraints.get_local_lines(),
                                              comm);
        ghosted = per_area;
        for (unsigned int k = 0; k < n; ++k)
          {
            if (!is_hanging[k])
              continue;
            const auto &dof = set.nodes[set.pairs[k].node].dofs[dim - 1];
            double      sum = 0, weight = 0;
            for (const auto &[master, c] :
                 *constraints.get_constraint_entries(dof))
              if (const double q = ghosted[master]; q > 0)
                {
                  sum += std::abs(c) * q;
                  weight += std::abs(c);
                }
            if (weight > 0)
              epsilon[k] = sum / weight * set.pairs[k].area;
          }
      }
    } // namespace

    template <int dim>
    AdaptivePenalty<dim>::AdaptivePenalty(const parameters::Contact &p,
                                          const bool                 strict)
        : lower(p.lower_bound)
        , upper(p.upper_bound)
        , freeze(p.freeze)
        , per_step(p.factor_update == parameters::FactorUpdate::step)
        , hold_predictor(p.factor_update == parameters::FactorUpdate::iteration)
        , strict(strict)
        , projection(p.adaptive_estimate ==
                     parameters::AdaptiveEstimate::projection)
        , damping(p.damping)
        , target(p.target_fraction)
    {}

    template <int dim>
    void AdaptivePenalty<dim>::estimate_at(const ContactSet<dim>     &set,
                                           const tools::ToolSet<dim> &tools,
                                           const SystemView          &system,
                                           const ContactState        &state,
                                           std::vector<double>       &eps,
                                           std::vector<double> &stiffness) const
    {
      const unsigned int n = set.pairs.size();
      // dv: at active nodes the velocity change that leaves exactly delta of
      // penetration at the end of the step, zero elsewhere (u' of the method).
      const double                  dt = system.dt;
      TrilinosWrappers::MPI::Vector dv(system.residual()), w(system.residual());
      dv = 0;
      for (unsigned int k = 0; k < n; ++k)
        if (set.pairs[k].active)
          {
            const auto  &pair  = set.pairs[k];
            const double delta = target * tools.allowed_penetration(pair.tool);
            const double move  = (-delta - pair.predicted_gap) / dt;
            for (unsigned int a = 0; a < dim; ++a)
              dv[set.nodes[pair.node].dofs[a]] += move * pair.normal[a];
          }
      dv.compress(VectorOperation::add);
      system.constraints().set_zero(dv);
      // projection: the method as published, F = n.(r_b + K_b dv); force: its
      // limit dv -> 0, F = n.r_b, the force the node carries now.
      if (projection)
        system.matrix().vmult(w, dv);
      else
        w = 0;
      w += system.residual();
      system.constraints().set_zero(w);

      eps.resize(n);
      stiffness.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto &pair  = set.pairs[k];
          const auto &dofs  = set.nodes[pair.node].dofs;
          double      force = 0, K_nn = 0;
          for (unsigned int a = 0; a < dim; ++a)
            {
              force += pair.normal[a] * w[dofs[a]];
              K_nn += pair.normal[a] * pair.normal[a] *
                      system.matrix().diag_element(dofs[a]);
            }
          // Stiffness in displacement units (N/mm): K_b carries 1/dt.
          stiffness[k] = std::max(K_nn, 0.) / dt;
          eps[k] =
            bounded(force / (target * tools.allowed_penetration(pair.tool)),
                    stiffness[k]);
          // Far from convergence the estimate can jump by orders of magnitude
          // between iterations; let it change by at most a factor 'damping'
          // per estimate, starting from the fixed penalty of the tool.
          const double last = start_factor(set, tools, state, k);
          if (last > 0)
            eps[k] = std::clamp(eps[k], last / damping, last * damping);
        }
    }

    template <int dim>
    double AdaptivePenalty<dim>::start_factor(const ContactSet<dim>     &set,
                                              const tools::ToolSet<dim> &tools,
                                              const ContactState        &state,
                                              const unsigned int k) const
    {
      const auto  &pair = set.pairs[k];
      const double last = state(pair.node, pair.tool).factor;
      return last > 0 ? last : tools.penalty_factor(pair.tool) * pair.area;
    }

    template <int dim>
    void AdaptivePenalty<dim>::record_statistics(
      const std::vector<bool>   &active,
      const std::vector<double> &epsilon,
      const std::vector<double> &stiffness_of,
      const MPI_Comm             comm)
    {
      const unsigned int n = active.size();
      min_factor           = std::numeric_limits<double>::max();
      max_factor           = 0;
      max_ratio            = 0;
      n_active             = 0;
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            ++n_active;
            min_factor = std::min(min_factor, epsilon[k]);
            max_factor = std::max(max_factor, epsilon[k]);
            if (stiffness_of[k] > 0)
              max_ratio = std::max(max_ratio, epsilon[k] / stiffness_of[k]);
          }
      min_factor = Utilities::MPI::min(min_factor, comm);
      max_factor = Utilities::MPI::max(max_factor, comm);
      max_ratio  = Utilities::MPI::max(max_ratio, comm);
      n_active   = Utilities::MPI::sum(n_active, comm);
      if (n_active == 0)
        min_factor = 0;
    }

    template <int dim>
    void AdaptivePenalty<dim>::estimate(const ContactSet<dim>     &set,
                                        const tools::ToolSet<dim> &tools,
                                        const SystemView          &system,
                                        ContactState              &state,
                                        std::vector<double>       &epsilon)
    {
      Assert(state.size() == set.nodes.size() * tools.size(),
             ExcInternalError());
      const unsigned int      n      = set.pairs.size();
      const std::vector<char> status = freeze_status(set);
      std::vector<bool>       active(n);
      for (unsigned int k = 0; k < n; ++k)
        active[k] = set.pairs[k].active;

      // Freeze only when the active set repeats on every rank: a decision
      // per rank would make the factors depend on the partition.
      const MPI_Comm comm = system.comm();
      const bool     reuse =
        Utilities::MPI::min(int(freeze && status == last_status &&
                                last_epsilon.size() == n),
                            comm) != 0;

      std::vector<double> eps, stiffness_of;
      epsilon.resize(n);
      // Both decisions are the same on every rank (collective calls below).
      if (per_step && held)
        {
          // Held within the solve: bounds that followed the iterate's
          // stiffness made Newton cycle between two iterates.
          epsilon      = last_epsilon;
          stiffness_of = last_stiffness;
        }
      else if (per_step || (hold_predictor && system.predictor))
        {
          // At a step's predictor the body is far from equilibrium (|r|/|f|
          // about 1) and n.r_b is not the force a node carries: the last
          // factors are kept there (doc/convergence.md). After a strict
          // correction within a per-step solve: the forces of this iterate
          // (|r|/|f| <= Strict check residual) first.
          if (refresh)
            record_estimate(set, tools, system, state);
          refresh = false;
          held    = per_step;
          // The last converged solve's estimate (or the fixed penalty), times
          // the strict scale, within the bounds at the solve's first iterate.
          // Read on every rank, with pairs or without: the first read
          // assembles the tangent (collective).
          const auto &K_b = system.matrix();
          stiffness_of.resize(n);
          for (unsigned int k = 0; k < n; ++k)
            {
              const auto &pair = set.pairs[k];
              double      K_nn = 0;
              for (unsigned int a = 0; a < dim; ++a)
                K_nn += pair.normal[a] * pair.normal[a] *
                        K_b.diag_element(set.nodes[pair.node].dofs[a]);
              stiffness_of[k] = std::max(K_nn, 0.) / system.dt;
              epsilon[k]      = bounded(start_factor(set, tools, state, k) *
                                     state(pair.node, pair.tool).scale,
                                   stiffness_of[k]);
            }
        }
      else
        {
          estimate_at(set, tools, system, state, eps, stiffness_of);
          // Hanging nodes take their masters' bounded estimate (their own
          // tangent diagonal is no stiffness of theirs), then their own
          // strict scale acts on it, as every other node's does.
          std::vector<bool> is_hanging(n, false);
          if (!reuse)
            {
              std::vector<double> masters(n);
              for (unsigned int k = 0; k < n; ++k)
                masters[k] = bounded(eps[k], stiffness_of[k]);
              interpolate_hanging(set,
                                  system.constraints(),
                                  system.residual(),
                                  is_hanging,
                                  masters);
              for (unsigned int k = 0; k < n; ++k)
                if (is_hanging[k])
                  eps[k] = masters[k];
            }
          for (unsigned int k = 0; k < n; ++k)
            {
              ContactRecord &record =
                state(set.pairs[k].node, set.pairs[k].tool);
              if (!reuse)
                record.factor = eps[k];
              else if (record.factor <= 0)
                record.factor = start_factor(set, tools, state, k);
              // The strict scale acts within the bounds: Upper bound bounds it.
              epsilon[k] = reuse ? last_epsilon[k]
                           : is_hanging[k]
                             ? eps[k] * record.scale
                             : bounded(eps[k] * record.scale, stiffness_of[k]);
            }
        }
      record_statistics(active, epsilon, stiffness_of, comm);
      last_status    = status;
      last_epsilon   = epsilon;
      last_stiffness = stiffness_of;
    }

    template <int dim>
    void AdaptivePenalty<dim>::at_point(const ContactSet<dim>     &set,
                                        const tools::ToolSet<dim> &tools,
                                        const SystemView          &system,
                                        ContactState              &state,
                                        std::vector<double>       &epsilon,
                                        const bool                 same_pairs)
    {
      // Line-search trials keep the factors of the iterate; new pairs are
      // estimated at once (which reads the trial's body system).
      if (!same_pairs)
        estimate(set, tools, system, state, epsilon);
    }

    template <int dim>
    bool AdaptivePenalty<dim>::at_iterate(const ContactSet<dim>     &set,
                                          const tools::ToolSet<dim> &tools,
                                          const SystemView          &system,
                                          ContactState              &state,
                                          std::vector<double>       &epsilon)
    {
      if (holds(set, tools, state, system.predictor, system.comm()))
        return false;
      estimate(set, tools, system, state, epsilon);
      return true;
    }

    template <int dim>
    bool AdaptivePenalty<dim>::holds(const ContactSet<dim>     &set,
                                     const tools::ToolSet<dim> &tools,
                                     const ContactState        &state,
                                     const bool                 predictor,
                                     const MPI_Comm             comm) const
    {
      // The branches of estimate() that do not read the system.
      if (per_step)
        return held;
      if (hold_predictor && predictor)
        return false; // reads the tangent's diagonal for the bounds
      // Frozen, and no record that would get its first factor.
      bool frozen = freeze && freeze_status(set) == last_status &&
                    last_epsilon.size() == set.pairs.size();
      for (unsigned int k = 0; frozen && k < set.pairs.size(); ++k)
        frozen = state(set.pairs[k].node, set.pairs[k].tool).factor > 0 ||
                 start_factor(set, tools, state, k) <= 0;
      return Utilities::MPI::min(int(frozen), comm) != 0;
    }

    template <int dim>
    void AdaptivePenalty<dim>::converged(const ContactSet<dim>     &set,
                                         const tools::ToolSet<dim> &tools,
                                         const SystemView          &system,
                                         ContactState              &state)
    {
      if (per_step)
        record_estimate(set, tools, system, state);
    }

    template <int dim>
    void AdaptivePenalty<dim>::record_estimate(const ContactSet<dim>     &set,
                                               const tools::ToolSet<dim> &tools,
                                               const SystemView &system,
                                               ContactState     &state) const
    {
      // At convergence n.r_b is the force each active node carries: the
      // estimate for the next solve. Open pairs keep what they had, so a
      // node that lifts off and lands again starts from its last factor.
      std::vector<double> eps, stiffness;
      estimate_at(set, tools, system, state, eps, stiffness);
      std::vector<bool> is_hanging;
      interpolate_hanging(set,
                          system.constraints(),
                          system.residual(),
                          is_hanging,
                          eps);
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        if (set.pairs[k].active)
          state(set.pairs[k].node, set.pairs[k].tool).factor = eps[k];
    }

    template <int dim>
    bool AdaptivePenalty<dim>::check_bound(const ContactSet<dim>     &set,
                                           const tools::ToolSet<dim> &tools,
                                           ContactState              &state,
                                           const MPI_Comm             comm,
                                           const bool relax) const
    {
      int again = 0;
      for (const auto &pair : set.pairs)
        {
          const double delta = tools.allowed_penetration(pair.tool);
          const double depth = -pair.predicted_gap;
          double      &scale = state(pair.node, pair.tool).scale;
          if (pair.active && depth > delta)
            {
              // 10 % beyond the proportional correction: the body's own
              // compliance makes the penetration fall less than 1/eps.
              scale *= 1.1 * depth / delta;
              again = 1;
            }
          else if (relax && (!pair.active || depth < 0.5 * delta))
            // Far inside the bound (or open): what made the estimate too soft
            // has passed; halve the scale towards 1 at most once per solve.
            scale = std::max(1., scale * std::max(0.5, depth / (0.5 * delta)));
        }
      return Utilities::MPI::max(again, comm) != 0;
    }

    template <int dim>
    bool AdaptivePenalty<dim>::finish_solve(const ContactSet<dim>     &set,
                                            const tools::ToolSet<dim> &tools,
                                            ContactState              &state,
                                            const MPI_Comm             comm)
    {
      return strict && check_bound(set, tools, state, comm, true);
    }

    template <int dim>
    bool AdaptivePenalty<dim>::tighten(const ContactSet<dim>     &set,
                                       const tools::ToolSet<dim> &tools,
                                       ContactState              &state,
                                       const MPI_Comm             comm)
    {
      const bool again = strict && check_bound(set, tools, state, comm, false);
      refresh          = again && per_step;
      return again;
    }

    template <int dim>
    std::string AdaptivePenalty<dim>::summary() const
    {
      std::ostringstream s;
      s << "  eps=[" << min_factor << ", " << max_factor
        << "] N/mm  max eps*dt/K_kk=" << max_ratio << "  active=" << n_active;
      return s.str();
    }

#define INSTANTIATE(dim) template class AdaptivePenalty<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE

    namespace
    {
      template <bool strict>
      bool register_adaptive()
      {
        return register_penalty_strategy(
          strict ? "adaptive-strict" : "adaptive",
          [](const parameters::Contact &p) {
            return std::make_unique<AdaptivePenalty<2>>(p, strict);
          },
          [](const parameters::Contact &p) {
            return std::make_unique<AdaptivePenalty<3>>(p, strict);
          });
      }
      [[maybe_unused]] const bool registered_adaptive =
        register_adaptive<false>();
      [[maybe_unused]] const bool registered_strict = register_adaptive<true>();
    } // namespace
  }   // namespace contact
} // namespace formsolve
