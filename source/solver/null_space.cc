#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/solver/null_space.h>

#include <map>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    NullSpace rigid_body_modes(const Mapping<dim>    &mapping,
                               const DoFHandler<dim> &dof_handler,
                               const IndexSet        &owned)
    {
      std::map<types::global_dof_index, Point<dim>> points;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);

      NullSpace          space;
      const unsigned int n = owned.n_elements();
      space.n_components   = dim;
      space.n_modes        = dim + dim * (dim - 1) / 2;
      space.modes.assign(space.n_modes * n, 0.);
      const unsigned int n_nodes = n / dim;
      space.x.assign(n_nodes, 0.);
      space.y.assign(n_nodes, 0.);
      space.z.assign(n_nodes, 0.);

      // The rotations about one point for all ranks: each rank's part of a
      // mode must continue its neighbours'.
      std::vector<Point<dim>> at(n);
      Tensor<1, dim>          sum;
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto p = points.find(owned.nth_index_in_set(i));
          Assert(p != points.end(), ExcInternalError());
          at[i] = p->second;
          sum += at[i];
        }
      const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
      // On every rank together: a rank that stopped alone would leave the
      // others waiting in the sums below.
      AssertThrow(Utilities::MPI::max(n % dim, comm) == 0,
                  ExcMessage("AMG null space: the owned DoFs are not whole "
                             "nodes"));
      const Point<dim> centroid(Utilities::MPI::sum(sum, comm) /
                                Utilities::MPI::sum(n, comm));
      for (unsigned int i = 0; i < n; ++i)
        {
          // Components are interleaved per node; a node's DoFs share their
          // support point.
          const unsigned int c = i % dim, node = i / dim;
          Assert(at[i].distance(at[node * dim]) <= 1e-12 * (1 + at[i].norm()),
                 ExcInternalError());
          const Tensor<1, dim> r = at[i] - centroid;
          space.modes[c * n + i] = 1.;
          // Rotation about axis k (3-D) or the normal (2-D): u = e_k x r.
          if (dim == 2)
            space.modes[2 * n + i] = c == 0 ? -r[1] : r[0];
          else
            for (unsigned int k = 0; k < 3; ++k)
              {
                const unsigned int a = (k + 1) % 3, b = (k + 2) % 3;
                space.modes[(3 + k) * n + i] =
                  c == a ? -r[b] : (c == b ? r[a] : 0.);
              }
          if (c == 0)
            {
              space.x[node] = at[i][0];
              space.y[node] = at[i][1];
              space.z[node] = dim == 3 ? at[i][dim - 1] : 0.;
            }
        }
      return space;
    }

#define INSTANTIATE(dim)                                            \
  template NullSpace rigid_body_modes<dim>(const Mapping<dim> &,    \
                                           const DoFHandler<dim> &, \
                                           const IndexSet &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
