#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/springback/section_profile.h>

#include <cmath>
#include <limits>
#include <map>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    template <int dim>
    std::vector<ProfilePoint> section_profile(const Release<dim>      &release,
                                              const state::State<dim> &state)
    {
      if constexpr (dim != 2)
        return {};
      else
        {
          const auto &dh    = release.dof_handler();
          const auto &fe    = dh.get_fe();
          const auto  owned = dh.locally_owned_dofs();
          std::map<types::global_dof_index, Point<dim>> reference, current;
          DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                               dh,
                                               reference);
          DoFTools::map_dofs_to_support_points(*state.mapping, dh, current);
          // The node layer nearest the mid-plane z = t/2 of the blank.
          const double t   = state.prm.geometry.thickness;
          double       off = std::numeric_limits<double>::max();
          for (const auto &[i, X] : reference)
            off = std::min(off, std::abs(X[1] - t / 2));
          off = Utilities::MPI::min(off, state.comm);
          // The x DoF of each owned mid-surface node, and its z DoF.
          std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
          std::map<types::global_dof_index, types::global_dof_index> z_of;
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->is_locally_owned() && release.in_part(cell))
              {
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  if (fe.system_to_component_index(i).first == 0 &&
                      owned.is_element(dofs[i]) &&
                      std::abs(std::abs(reference[dofs[i]][1] - t / 2) - off) <
                        1e-9 * t &&
                      reference[dofs[i]][1] >= t / 2 - 1e-9 * t)
                    for (unsigned int j = 0; j < dofs.size(); ++j)
                      if (fe.system_to_component_index(j).first == 1 &&
                          reference[dofs[j]].distance(reference[dofs[i]]) <
                            1e-12 * t)
                        z_of[dofs[i]] = dofs[j];
              }
          const auto         &u = release.displacement();
          std::vector<double> mine; // X0, x, z, u_x, u_z per node
          for (const auto &[ix, iz] : z_of)
            for (const double v : {reference[ix][0],
                                   current[ix][0],
                                   current[ix][1],
                                   u[ix],
                                   u[iz]})
              mine.push_back(v);
          std::vector<ProfilePoint> all;
          for (const auto &part : Utilities::MPI::all_gather(state.comm, mine))
            for (std::size_t k = 0; k + 4 < part.size(); k += 5)
              {
                ProfilePoint p;
                p.X0     = part[k];
                p.end    = {{part[k + 1], part[k + 2]}};
                p.sprung = {
                  {part[k + 1] + part[k + 3], part[k + 2] + part[k + 4]}};
                all.push_back(p);
              }
          return all;
        }
    }

#define INSTANTIATE(dim)                              \
  template std::vector<ProfilePoint> section_profile( \
    const Release<dim> &,                             \
    const state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
