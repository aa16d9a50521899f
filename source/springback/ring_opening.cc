#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/springback/ring_opening.h>

#include <limits>
#include <map>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    template <int dim>
    RingOpening ring_opening(const Release<dim> &release,
                             const Mapping<dim> &configuration)
    {
      RingOpening out;
      if constexpr (dim == 3)
        {
          const auto &dh    = release.dof_handler();
          const auto &fe    = dh.get_fe();
          const auto &unit  = fe.get_unit_support_points();
          const auto  owned = dh.locally_owned_dofs();
          const auto &u     = release.displacement();
          std::vector<types::global_dof_index>      dofs(fe.n_dofs_per_cell());
          std::map<types::global_dof_index, double> opening;
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->is_locally_owned() && release.in_part(cell))
              {
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  if (fe.system_to_component_index(i).first == 0 &&
                      owned.is_element(dofs[i]))
                    {
                      const auto x =
                        configuration.transform_unit_to_real_cell(cell,
                                                                  unit[i]);
                      // On the symmetry plane u_x was 0: x is 0 there.
                      if (std::abs(x[0]) < 1e-9 * (1 + x.norm()) && x[1] > 0)
                        opening[dofs[i]] = 2 * u[dofs[i]];
                    }
              }
          double sum = 0, low = std::numeric_limits<double>::max(), high = -low;
          for (const auto &[i, w] : opening)
            {
              sum += w;
              low  = std::min(low, w);
              high = std::max(high, w);
            }
          const MPI_Comm comm = dh.get_communicator();
          out.nodes           = Utilities::MPI::sum(opening.size(), comm);
          if (out.nodes > 0)
            {
              out.mean = Utilities::MPI::sum(sum, comm) / out.nodes;
              out.low  = Utilities::MPI::min(low, comm);
              out.high = Utilities::MPI::max(high, comm);
            }
        }
      (void)release;
      (void)configuration;
      return out;
    }

#define INSTANTIATE(dim) \
  template RingOpening ring_opening(const Release<dim> &, const Mapping<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
