#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/trimming/earlier_values.h>
#include <formsolve/trimming/part_transfer.h>

#include <limits>
#include <map>

namespace formsolve
{
  namespace trimming
  {
    using namespace dealii;

    namespace
    {
      /// The displacements @p fields of @p earlier at @p part's nodes
      /// (reference configuration, eq. 14f).
      template <int dim>
      std::vector<state::VectorType>
      on_nodes(const state::State<dim>                      &earlier,
               const std::vector<const state::VectorType *> &fields,
               const state::State<dim>                      &part)
      {
        // The part's nodes, each seen from inside one of its cells: a point
        // next to a node of the earlier mesh is slow to place (every cell
        // around it is a candidate), so the field is evaluated at e and 2e
        // towards the cell's centre (unit coordinates) and extrapolated back,
        // 2 u(e) - u(2e), exact to O(e^2) on the earlier cell's polynomial.
        constexpr double        e     = 1e-4;
        const auto             &fe    = part.fe;
        const auto              units = fe.get_unit_support_points();
        std::vector<Point<dim>> near, far;
        std::vector<std::array<types::global_dof_index, dim>> node_dofs;
        std::vector<bool>                    seen(part.owned.n_elements());
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : part.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const auto [c, base] = fe.system_to_component_index(i);
                  if (c != 0 || !part.owned.is_element(dofs[i]) ||
                      seen[part.owned.index_within_set(dofs[i])])
                    continue;
                  seen[part.owned.index_within_set(dofs[i])] = true;
                  Point<dim> centre;
                  for (unsigned int d = 0; d < dim; ++d)
                    centre[d] = 0.5;
                  for (const double s : {e, 2 * e})
                    (s == e ? near : far)
                      .push_back(
                        part.reference_mapping.transform_unit_to_real_cell(
                          cell,
                          units[i] + s * (centre - units[i])));
                  std::array<types::global_dof_index, dim> n;
                  for (unsigned int j = 0; j < dofs.size(); ++j)
                    if (fe.system_to_component_index(j).second == base)
                      n[fe.system_to_component_index(j).first] = dofs[j];
                  node_dofs.push_back(n);
                }
            }
        std::vector<Point<dim>> both(near);
        both.insert(both.end(), far.begin(), far.end());
        Utilities::MPI::RemotePointEvaluation<dim> at_nodes(1e-6, true);
        locate(earlier, both, at_nodes, "nodes");
        const auto on_part = [&](const state::VectorType &field) {
          state::VectorType ghosted(earlier.owned,
                                    earlier.relevant,
                                    earlier.comm);
          ghosted = field;
          const auto values =
            VectorTools::point_values<dim>(at_nodes,
                                           earlier.dof_handler,
                                           ghosted);
          state::VectorType u(part.owned, part.comm);
          const std::size_t n = near.size();
          for (std::size_t k = 0; k < n; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              u[node_dofs[k][d]] = 2 * values[k][d] - values[n + k][d];
          u.compress(VectorOperation::insert);
          return u;
        };
        std::vector<state::VectorType> out;
        for (const auto *f : fields)
          out.push_back(on_part(*f));
        return out;
      }

      /// At each material point of @p part the nearest earlier one's
      /// history.
      template <int dim>
      void history_at_points(const state::State<dim> &earlier,
                             state::State<dim>       &part)
      {
        const auto &fe = part.fe;
        // The history: at each material point the nearest earlier one's.
        FEValues<dim>           fe_values(part.reference_mapping,
                                fe,
                                part.history_rule,
                                update_quadrature_points);
        std::vector<Point<dim>> points;
        for (const auto &cell : part.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              for (const auto &x : fe_values.get_quadrature_points())
                points.push_back(x);
            }
        Utilities::MPI::RemotePointEvaluation<dim> at_points(1e-6, true);
        locate(earlier, points, at_points, "material points");
        const auto        &rule = earlier.history_rule;
        const unsigned int n_values =
          state::QuadraturePointHistory().number_of_values();
        std::vector<std::vector<double>> values(points.size(),
                                                std::vector<double>(n_values));
        for (unsigned int v = 0; v < n_values; ++v)
          {
            const auto column = cell_values(
              earlier,
              at_points,
              [&](const auto &cell, const Point<dim> &x) {
                unsigned int best = 0;
                for (unsigned int q = 1; q < rule.size(); ++q)
                  if (x.distance(rule.point(q)) < x.distance(rule.point(best)))
                    best = q;
                std::vector<double> packed;
                earlier.history.get_data(cell)[best]->pack_values(packed);
                return packed[v];
              });
            for (std::size_t p = 0; p < points.size(); ++p)
              values[p][v] = column[p];
          }
        std::size_t p = 0;
        for (const auto &cell : part.tria.active_cell_iterators())
          if (cell->is_locally_owned())
            for (auto &h : part.history.get_data(cell))
              h->unpack_values(values[p++]);
      }
    } // namespace

    template <int dim>
    void refine_like(const state::State<dim> &earlier,
                     const unsigned int       level,
                     state::State<dim>       &part)
    {
      for (;;)
        {
          std::vector<Point<dim>> centres;
          std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
          for (const auto &cell : part.tria.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                centres.push_back(cell->center());
                cells.push_back(cell);
              }
          Utilities::MPI::RemotePointEvaluation<dim> cache(1e-6, true);
          locate(earlier, centres, cache, "cell centres");
          const auto levels =
            cell_values(earlier, cache, [](const auto &cell, const auto &) {
              return double(cell->level());
            });
          unsigned int flagged = 0;
          for (std::size_t i = 0; i < cells.size(); ++i)
            if (level + cells[i]->level() < levels[i] - 0.5)
              {
                cells[i]->set_refine_flag();
                ++flagged;
              }
          if (Utilities::MPI::sum(flagged, part.comm) == 0)
            break;
          part.tria.execute_coarsening_and_refinement();
        }
      part.setup_dofs();
    }

    template <int dim>
    void transfer_part(state::State<dim>               &earlier,
                       const state::VectorType         &formed,
                       const state::VectorType         &shape,
                       const state::HistoryUpdate<dim> &update,
                       state::State<dim>               &part)
    {
      // The volume errors of the end of forming go over (adapt.cc does
      // the same around a refinement).
      earlier.set_shape(formed);
      update.exchange_volume_offsets(earlier.dof_handler,
                                     *earlier.mapping,
                                     earlier.history);

      const auto fields      = on_nodes(earlier, {&formed, &shape}, part);
      const auto part_formed = fields[0], part_shape = fields[1];
      history_at_points(earlier, part);

      part.set_shape(part_formed);
      update.exchange_volume_offsets(part.dof_handler,
                                     *part.mapping,
                                     part.history);
      part.set_shape(part_shape);
      part.update_contact_areas();
    }

#define INSTANTIATE(dim)                                         \
  template void refine_like(const state::State<dim> &,           \
                            const unsigned int,                  \
                            state::State<dim> &);                \
  template void transfer_part(state::State<dim> &,               \
                              const state::VectorType &,         \
                              const state::VectorType &,         \
                              const state::HistoryUpdate<dim> &, \
                              state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace trimming
} // namespace formsolve
