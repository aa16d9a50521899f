#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/fe/fe_tools.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/history_transfer.h>

namespace formsolve
{
  namespace refinement
  {
    using namespace dealii;

    template <int dim>
    HistoryTransfer<dim>::HistoryTransfer(const unsigned int     degree,
                                          const Quadrature<dim> &quadrature)
        : fe(degree)
        , quadrature(quadrature)
        , to_fe(fe.n_dofs_per_cell(), quadrature.size())
        , to_points(quadrature.size(), fe.n_dofs_per_cell())
    {
      FETools::compute_projection_from_quadrature_points_matrix(fe,
                                                                quadrature,
                                                                quadrature,
                                                                to_fe);
      FETools::compute_interpolation_to_quadrature_points_matrix(fe,
                                                                 quadrature,
                                                                 to_points);
      n_values = simulation::QuadraturePointHistory().number_of_values();
    }

    template <int dim>
    void HistoryTransfer<dim>::prepare(
      parallel::distributed::Triangulation<dim> &triangulation,
      simulation::HistoryStorage<dim>           &history)
    {
      tria                   = &triangulation;
      const unsigned int n_q = quadrature.size(), n_dofs = fe.n_dofs_per_cell();
      // Per cell: n_dofs x n_values coefficients, value-major.
      old_values.assign(tria->n_active_cells(), {});
      std::vector<double> packed;
      Vector<double>      at_points(n_q), coefficients(n_dofs);
      for (const auto &cell : tria->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto data = history.get_data(cell);
            Assert(data.size() == n_q, ExcInternalError());
            auto &out = old_values[cell->active_cell_index()];
            out.resize(n_dofs * n_values);
            for (unsigned int v = 0; v < n_values; ++v)
              {
                for (unsigned int q = 0; q < n_q; ++q)
                  {
                    data[q]->pack_values(packed);
                    at_points[q] = packed[v];
                  }
                to_fe.vmult(coefficients, at_points);
                std::copy(coefficients.begin(),
                          coefficients.end(),
                          out.begin() + v * n_dofs);
              }
          }

      const unsigned int n = n_dofs, nv = n_values;
      const FE_DGQ<dim> &element = fe;
      auto               refine = [&element, n, nv](const auto                &parent,
                                      const std::vector<double> &values) {
        std::vector<std::vector<double>> children(parent->n_children());
        Vector<double>                   from(n), to(n);
        for (unsigned int c = 0; c < parent->n_children(); ++c)
          {
            children[c].resize(n * nv);
            const auto &P =
              element.get_prolongation_matrix(c, parent->refinement_case());
            for (unsigned int v = 0; v < nv; ++v)
              {
                std::copy(values.begin() + v * n,
                          values.begin() + (v + 1) * n,
                          from.begin());
                P.vmult(to, from);
                std::copy(to.begin(), to.end(), children[c].begin() + v * n);
              }
          }
        return children;
      };
      auto coarsen =
        [&element, n, nv](const auto                             &parent,
                          const std::vector<std::vector<double>> &children) {
          // FE_DGQ's restriction is additive: the parent's coefficients are
          // the sum of R_c times each child's.
          std::vector<double> values(n * nv, 0.);
          Vector<double>      from(n), to(n);
          for (unsigned int c = 0; c < children.size(); ++c)
            {
              const auto &R =
                element.get_restriction_matrix(c, parent->refinement_case());
              for (unsigned int v = 0; v < nv; ++v)
                {
                  std::copy(children[c].begin() + v * n,
                            children[c].begin() + (v + 1) * n,
                            from.begin());
                  R.vmult(to, from);
                  for (unsigned int i = 0; i < n; ++i)
                    values[v * n + i] += to[i];
                }
            }
          return values;
        };
      transfer = std::make_unique<
        parallel::distributed::CellDataTransfer<dim, dim, CellValues>>(
        *tria,
        /*variable size*/ false,
        refine,
        coarsen);
      transfer->prepare_for_coarsening_and_refinement(old_values);
    }

    template <int dim>
    void
    HistoryTransfer<dim>::interpolate(simulation::HistoryStorage<dim> &history)
    {
      Assert(transfer, ExcInternalError());
      CellValues new_values(tria->n_active_cells());
      transfer->unpack(new_values);
      const unsigned int n_q = quadrature.size(), n_dofs = fe.n_dofs_per_cell();
      Vector<double>     coefficients(n_dofs), at_points(n_q);
      std::vector<std::vector<double>> values(n_q,
                                              std::vector<double>(n_values));
      for (const auto &cell : tria->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &in = new_values[cell->active_cell_index()];
            Assert(in.size() == n_dofs * n_values, ExcInternalError());
            for (unsigned int v = 0; v < n_values; ++v)
              {
                std::copy(in.begin() + v * n_dofs,
                          in.begin() + (v + 1) * n_dofs,
                          coefficients.begin());
                to_points.vmult(at_points, coefficients);
                for (unsigned int q = 0; q < n_q; ++q)
                  values[q][v] = at_points[q];
              }
            const auto data = history.get_data(cell);
            for (unsigned int q = 0; q < n_q; ++q)
              data[q]->unpack_values(values[q]);
          }
      transfer.reset();
      old_values.clear();
    }

#define INSTANTIATE(dim) template class HistoryTransfer<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace refinement
} // namespace formsolve
