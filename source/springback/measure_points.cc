#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/springback/measure_points.h>

#include <limits>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    template <int dim>
    std::vector<PointSpringback>
    springback_at(const Release<dim>                     &release,
                  const state::State<dim>                &state,
                  const std::vector<std::vector<double>> &points)
    {
      const auto                  &dh      = release.dof_handler();
      const auto                  &fe      = dh.get_fe();
      const auto                  &unit    = fe.get_unit_support_points();
      const auto                  &mapping = *state.mapping;
      std::vector<PointSpringback> out;
      for (const auto &coordinates : points)
        {
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = coordinates[d];
          // The nearest node of this rank's cells, then of all.
          double best = std::numeric_limits<double>::max();
          typename DoFHandler<dim>::active_cell_iterator at;
          unsigned int                                   node = 0;
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->is_locally_owned() && release.in_part(cell))
              for (unsigned int i = 0; i < unit.size(); ++i)
                {
                  const double d =
                    mapping.transform_unit_to_real_cell(cell, unit[i])
                      .distance(p);
                  if (d < best)
                    {
                      best = d;
                      at   = cell;
                      node = i;
                    }
                }
          const auto nearest = Utilities::MPI::min_max_avg(best, state.comm);
          std::vector<double> values(10, 0.);
          if (Utilities::MPI::this_mpi_process(state.comm) == nearest.min_index)
            {
              FEValues<dim> fv(mapping,
                               fe,
                               Quadrature<dim>(unit[node]),
                               update_values | update_jacobians |
                                 update_quadrature_points);
              fv.reinit(at);
              std::vector<Tensor<1, dim>> u(1);
              fv[FEValuesExtractors::Vector(0)]
                .get_function_values(release.displacement(), u);
              Tensor<1, dim> n;
              for (unsigned int d = 0; d < dim; ++d)
                n[d] = fv.jacobian(0)[d][dim - 1];
              n /= n.norm();
              for (unsigned int d = 0; d < dim; ++d)
                {
                  values[d]     = fv.quadrature_point(0)[d];
                  values[3 + d] = n[d];
                  values[6 + d] = u[0][d];
                }
              values[9] = n * u[0];
            }
          values =
            Utilities::MPI::broadcast(state.comm, values, nearest.min_index);
          PointSpringback s;
          for (unsigned int d = 0; d < 3; ++d)
            {
              s.node[d]         = values[d];
              s.normal[d]       = values[3 + d];
              s.displacement[d] = values[6 + d];
            }
          s.along_normal = values[9];
          out.push_back(s);
        }
      return out;
    }

#define INSTANTIATE(dim)                               \
  template std::vector<PointSpringback> springback_at( \
    const Release<dim> &,                              \
    const state::State<dim> &,                         \
    const std::vector<std::vector<double>> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
