#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/contact/penalty_estimator.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    void FixedPenalty<dim>::estimate(const ContactSet<dim>     &set,
                                     const tools::ToolSet<dim> &tools,
                                     const SystemView &,
                                     std::vector<double> &epsilon)
    {
      epsilon.resize(set.pairs.size());
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        epsilon[k] =
          tools.penalty_factor(set.pairs[k].tool) * set.pairs[k].area;
    }

    template <int dim>
    AdaptivePenalty<dim>::AdaptivePenalty(const parameters::Contact &p,
                                          const bool                 strict)
        : lower(p.lower_bound)
        , upper(p.upper_bound)
        , freeze(p.freeze)
        , strict(strict)
        , projection(p.adaptive_estimate == "projection")
        , damping(p.damping)
        , target(p.target_fraction)
    {}

    template <int dim>
    void AdaptivePenalty<dim>::estimate(const ContactSet<dim>     &set,
                                        const tools::ToolSet<dim> &tools,
                                        const SystemView          &system,
                                        std::vector<double>       &epsilon)
    {
      Assert(system.residual != nullptr && system.matrix != nullptr,
             ExcInternalError());
      const unsigned int n = set.pairs.size();
      std::vector<bool>  active(n);
      for (unsigned int k = 0; k < n; ++k)
        active[k] = set.pairs[k].active;
      if (scale.size() != set.nodes.size() * tools.size())
        {
          scale.assign(set.nodes.size() * tools.size(), 1.);
          previous.assign(set.nodes.size() * tools.size(), 0.);
        }

      // Every rank takes part in the vector operations below, so freezing is
      // decided per rank but the collective calls are made regardless.
      const bool reuse =
        freeze && active == last_active && last_epsilon.size() == n;

      // dv: at active nodes the velocity change that leaves exactly delta of
      // penetration at the end of the step, zero elsewhere (u' of the method).
      const double                  dt = system.dt;
      TrilinosWrappers::MPI::Vector dv(*system.residual), w(*system.residual);
      dv = 0;
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            const auto  &pair  = set.pairs[k];
            const double delta = target * tools.allowed_penetration(pair.tool);
            const double move  = (-delta - pair.predicted_gap) / dt;
            for (unsigned int a = 0; a < dim; ++a)
              dv[set.nodes[pair.node].dofs[a]] += move * pair.normal[a];
          }
      dv.compress(VectorOperation::add);
      system.constraints->set_zero(dv);
      // projection: the method as published, F = n.(r_b + K_b dv); force: its
      // limit dv -> 0, F = n.r_b, the force the node carries now.
      if (projection)
        system.matrix->vmult(w, dv);
      else
        w = 0;
      w += *system.residual;
      system.constraints->set_zero(w);

      epsilon.resize(n);
      min_factor = std::numeric_limits<double>::max();
      max_factor = 0;
      max_ratio  = 0;
      n_active   = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto &pair  = set.pairs[k];
          const auto &dofs  = set.nodes[pair.node].dofs;
          double      force = 0, K_nn = 0;
          for (unsigned int a = 0; a < dim; ++a)
            {
              force += pair.normal[a] * w[dofs[a]];
              K_nn += pair.normal[a] * pair.normal[a] *
                      system.matrix->diag_element(dofs[a]);
            }
          // Stiffness in displacement units (N/mm): K_b carries 1/dt.
          const double stiffness = std::max(K_nn, 0.) / dt;
          double       eps =
            std::clamp(force / (target * tools.allowed_penetration(pair.tool)),
                       lower * stiffness,
                       upper * stiffness);
          // Far from convergence the estimate can jump by orders of magnitude
          // between iterations; let it change by at most a factor 'damping'
          // per estimate, starting from the fixed penalty of the tool.
          double &last = previous[pair.node * tools.size() + pair.tool];
          if (last <= 0)
            last = tools.penalty_factor(pair.tool) * pair.area;
          if (last > 0)
            eps = std::clamp(eps, last / damping, last * damping);
          if (!reuse)
            last = eps;
          epsilon[k] = reuse
                         ? last_epsilon[k]
                         : eps * scale[pair.node * tools.size() + pair.tool];
          if (active[k])
            {
              ++n_active;
              min_factor = std::min(min_factor, epsilon[k]);
              max_factor = std::max(max_factor, epsilon[k]);
              if (stiffness > 0)
                max_ratio = std::max(max_ratio, epsilon[k] / stiffness);
            }
        }
      const MPI_Comm comm = system.residual->get_mpi_communicator();
      min_factor          = Utilities::MPI::min(min_factor, comm);
      max_factor          = Utilities::MPI::max(max_factor, comm);
      max_ratio           = Utilities::MPI::max(max_ratio, comm);
      n_active            = Utilities::MPI::sum(n_active, comm);
      if (n_active == 0)
        min_factor = 0;
      last_active  = active;
      last_epsilon = epsilon;
    }

    template <int dim>
    bool AdaptivePenalty<dim>::finish_step(ContactSet<dim>           &set,
                                           const tools::ToolSet<dim> &tools,
                                           const MPI_Comm             comm)
    {
      last_epsilon.clear();
      if (!strict)
        return false;
      int again = 0;
      for (const auto &pair : set.pairs)
        {
          const double delta = tools.allowed_penetration(pair.tool);
          const double depth = -pair.predicted_gap;
          if (pair.active && depth > delta)
            {
              // 10 % beyond the proportional correction: the body's own
              // compliance makes the penetration fall less than 1/eps.
              scale[pair.node * tools.size() + pair.tool] *=
                1.1 * depth / delta;
              again = 1;
            }
        }
      return Utilities::MPI::max(again, comm) != 0;
    }

    template <int dim>
    std::string AdaptivePenalty<dim>::summary() const
    {
      std::ostringstream s;
      s << "  eps=[" << min_factor << ", " << max_factor
        << "] N/mm  max eps*dt/K_kk=" << max_ratio << "  active=" << n_active;
      return s.str();
    }

    template <int dim>
    AugmentedLagrangian<dim>::AugmentedLagrangian(
      std::unique_ptr<PenaltyEstimator<dim>> inner)
        : inner(std::move(inner))
    {}

    template <int dim>
    bool AugmentedLagrangian<dim>::finish_step(ContactSet<dim>           &set,
                                               const tools::ToolSet<dim> &tools,
                                               const MPI_Comm             comm)
    {
      inner->finish_step(set, tools, comm);
      // Pairs out of search distance lose their multiplier.
      std::vector<double> shifts(set.nodes.size() * tools.size(), 0.);
      int                 again = 0;
      for (const auto &pair : set.pairs)
        {
          // Uzawa: lambda <- <lambda - eps g>, as a shift with eps fixed.
          shifts[pair.node * tools.size() + pair.tool] =
            std::max(0., pair.shift - pair.predicted_gap);
          if (pair.active &&
              -pair.predicted_gap > tools.allowed_penetration(pair.tool))
            again = 1;
        }
      set.shifts.swap(shifts);
      return Utilities::MPI::max(again, comm) != 0;
    }

    template <int dim>
    std::unique_ptr<PenaltyEstimator<dim>>
    create_penalty_estimator(const parameters::Contact &p)
    {
      if (p.penalty_strategy == "augmented-lagrangian")
        {
          parameters::Contact inner = p;
          inner.penalty_strategy    = p.al_penalty;
          return std::make_unique<AugmentedLagrangian<dim>>(
            create_penalty_estimator<dim>(inner));
        }
      if (p.penalty_strategy == "adaptive")
        return std::make_unique<AdaptivePenalty<dim>>(p, false);
      if (p.penalty_strategy == "adaptive-strict")
        return std::make_unique<AdaptivePenalty<dim>>(p, true);
      AssertThrow(p.penalty_strategy == "fixed",
                  ExcMessage("Contact/Penalty strategy: '" +
                             p.penalty_strategy + "' is not available"));
      return std::make_unique<FixedPenalty<dim>>();
    }

    template class FixedPenalty<2>;
    template class FixedPenalty<3>;
    template class AdaptivePenalty<2>;
    template class AdaptivePenalty<3>;
    template class AugmentedLagrangian<2>;
    template class AugmentedLagrangian<3>;
    template std::unique_ptr<PenaltyEstimator<2>>
    create_penalty_estimator<2>(const parameters::Contact &);
    template std::unique_ptr<PenaltyEstimator<3>>
    create_penalty_estimator<3>(const parameters::Contact &);
  } // namespace contact
} // namespace formsolve
