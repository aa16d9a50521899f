#include <formsolve/contact/contact_law.h>
#include <formsolve/contact/contact_statistics.h>
#include <formsolve/model/dimensions.h>

#include <cmath>
#include <limits>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    ContactStatistics<dim> statistics(const tools::ToolSet<dim> &tools,
                                      const ContactSet<dim>     &set,
                                      const std::vector<double> &epsilon,
                                      const double               v0,
                                      const double               dt,
                                      const MPI_Comm             comm)
    {
      ContactStatistics<dim> s;
      s.tool_force.resize(tools.size());
      s.tool_wall_force.assign(tools.size(), 0.);
      s.tool_wall_area.assign(tools.size(), 0.);
      s.force_travel = tools.punch_travel();
      s.tool_max_penetration.assign(tools.size(), 0.);
      double sum_penetration = 0;
      double eps_min = std::numeric_limits<double>::max(), eps_max = 0;
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        {
          const auto &pair = set.pairs[k];
          s.n_locked += pair.locked;
          if (!pair.active)
            continue;
          const auto f =
            penalty_friction_force(pair,
                                   epsilon[k],
                                   tools.friction_coefficient(pair.tool),
                                   v0,
                                   dt,
                                   false);
          s.tool_force[pair.tool] -= f.force;
          if (std::abs(pair.normal[dim - 1]) < 0.1)
            {
              s.tool_wall_force[pair.tool] += std::abs(f.force * pair.normal);
              s.tool_wall_area[pair.tool] += pair.area;
            }
          ++s.n_active;
          const double p = std::max(0., -pair.predicted_gap);
          s.tool_max_penetration[pair.tool] =
            std::max(s.tool_max_penetration[pair.tool], p);
          sum_penetration += p;
          s.n_over_allowed += p > tools.allowed_penetration(pair.tool);
          eps_min = std::min(eps_min, epsilon[k]);
          eps_max = std::max(eps_max, epsilon[k]);
        }
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          s.tool_force[t] = Utilities::MPI::sum(s.tool_force[t], comm);
          s.tool_wall_force[t] =
            Utilities::MPI::sum(s.tool_wall_force[t], comm);
          s.tool_wall_area[t] = Utilities::MPI::sum(s.tool_wall_area[t], comm);
          s.tool_max_penetration[t] =
            Utilities::MPI::max(s.tool_max_penetration[t], comm);
          s.max_penetration =
            std::max(s.max_penetration, s.tool_max_penetration[t]);
        }
      sum_penetration    = Utilities::MPI::sum(sum_penetration, comm);
      s.n_active         = Utilities::MPI::sum(s.n_active, comm);
      s.n_over_allowed   = Utilities::MPI::sum(s.n_over_allowed, comm);
      s.n_locked         = Utilities::MPI::sum(s.n_locked, comm);
      s.mean_penetration = s.n_active > 0 ? sum_penetration / s.n_active : 0.;
      eps_min            = Utilities::MPI::min(eps_min, comm);
      s.max_factor       = Utilities::MPI::max(eps_max, comm);
      s.min_factor       = s.n_active > 0 ? eps_min : 0.;
      return s;
    }

#define INSTANTIATE(dim)                                                  \
  template ContactStatistics<dim> statistics(const tools::ToolSet<dim> &, \
                                             const ContactSet<dim> &,     \
                                             const std::vector<double> &, \
                                             double,                      \
                                             double,                      \
                                             MPI_Comm);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace contact
} // namespace formsolve
