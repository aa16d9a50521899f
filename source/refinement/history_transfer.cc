#include <deal.II/distributed/cell_data_transfer.templates.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/history_transfer.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace formsolve
{
  namespace refinement
  {
    using namespace dealii;

    template <int dim>
    HistoryTransfer<dim>::HistoryTransfer(
      const Quadrature<dim>        &quadrature,
      const Mapping<dim>           &mapping,
      const model::Kinematics<dim> &kinematics)
        : quadrature(quadrature)
        , nearest(GeometryInfo<dim>::max_children_per_cell,
                  std::vector<unsigned int>(quadrature.size()))
        , kinematics(kinematics)
        , fe_values(mapping,
                    fe,
                    quadrature,
                    update_JxW_values | update_quadrature_points)
    {
      // p4est refines isotropically: child k is the part of the unit cell
      // at its vertex k.
      const unsigned int n_q = quadrature.size();
      for (unsigned int k = 0; k < nearest.size(); ++k)
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Point<dim> x =
              GeometryInfo<dim>::child_to_cell_coordinates(quadrature.point(q),
                                                           k);
            double best = std::numeric_limits<double>::max();
            for (unsigned int p = 0; p < n_q; ++p)
              if (x.distance(quadrature.point(p)) < best - 1e-12)
                {
                  best          = x.distance(quadrature.point(p));
                  nearest[k][q] = p;
                }
          }
      n_values = state::QuadraturePointHistory().number_of_values();
    }

    template <int dim>
    void HistoryTransfer<dim>::volumes(const CellIterator  &cell,
                                       std::vector<double> &weights)
    {
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        weights.push_back(fe_values.JxW(q) * kinematics.volume_factor(
                                               fe_values.quadrature_point(q)));
    }

    template <int dim>
    void HistoryTransfer<dim>::range(const CellValues          &cells,
                                     const std::vector<double> &weights,
                                     std::vector<double>       &mean,
                                     std::vector<double>       &lower,
                                     std::vector<double>       &upper) const
    {
      const unsigned int n_q = quadrature.size();
      Assert(weights.size() == cells.size() * n_q, ExcInternalError());
      const double volume = std::accumulate(weights.begin(), weights.end(), 0.);
      mean.assign(n_values, 0.);
      lower.assign(n_values, std::numeric_limits<double>::max());
      upper.assign(n_values, std::numeric_limits<double>::lowest());
      for (unsigned int k = 0; k < cells.size(); ++k)
        for (unsigned int v = 0; v < n_values; ++v)
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double x = cells[k][v * n_q + q];
              mean[v] += weights[k * n_q + q] * x / volume;
              lower[v] = std::min(lower[v], x);
              upper[v] = std::max(upper[v], x);
            }
      // A weighted mean lies in the range, but for round-off.
      for (unsigned int v = 0; v < n_values; ++v)
        mean[v] = std::clamp(mean[v], lower[v], upper[v]);
    }

    template <int dim>
    void HistoryTransfer<dim>::limit(CellValues                &cells,
                                     const std::vector<double> &weights,
                                     const std::vector<double> &mean,
                                     const std::vector<double> &lower,
                                     const std::vector<double> &upper) const
    {
      const unsigned int  n_q = quadrature.size();
      std::vector<double> current_mean, low, high;
      range(cells, weights, current_mean, low, high);
      for (unsigned int v = 0; v < n_values; ++v)
        {
          // One factor for the whole family keeps its mean.
          double alpha = 1;
          for (const auto &cell : cells)
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const double d = cell[v * n_q + q] - current_mean[v];
                if (mean[v] + d > upper[v])
                  alpha = std::min(alpha, (upper[v] - mean[v]) / d);
                else if (mean[v] + d < lower[v])
                  alpha = std::min(alpha, (lower[v] - mean[v]) / d);
              }
          for (auto &cell : cells)
            for (unsigned int q = 0; q < n_q; ++q)
              {
                double &x = cell[v * n_q + q];
                x         = std::clamp(mean[v] + alpha * (x - current_mean[v]),
                               lower[v],
                               upper[v]);
              }
        }
    }

    template <int dim>
    std::vector<std::vector<double>>
    HistoryTransfer<dim>::refine(const CellIterator        &parent,
                                 const std::vector<double> &values)
    {
      Assert(parent->refinement_case() ==
               RefinementCase<dim>::isotropic_refinement,
             ExcNotImplemented());
      const unsigned int n_q = quadrature.size(), n = parent->n_children();
      CellValues         children(n, std::vector<double>(n_values * n_q));
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int v = 0; v < n_values; ++v)
          for (unsigned int q = 0; q < n_q; ++q)
            children[k][v * n_q + q] = values[v * n_q + nearest[k][q]];
      std::vector<double> old_weights, new_weights, mean, lower, upper;
      volumes(parent, old_weights);
      for (unsigned int k = 0; k < n; ++k)
        volumes(parent->child(k), new_weights);
      range(CellValues{values}, old_weights, mean, lower, upper);
      limit(children, new_weights, mean, lower, upper);
      return children;
    }

    template <int dim>
    std::vector<double>
    HistoryTransfer<dim>::coarsen(const CellIterator &parent,
                                  const CellValues   &children)
    {
      Assert(parent->refinement_case() ==
               RefinementCase<dim>::isotropic_refinement,
             ExcNotImplemented());
      const unsigned int  n_q = quadrature.size();
      std::vector<double> old_weights, new_weights, mean, lower, upper;
      for (unsigned int k = 0; k < children.size(); ++k)
        volumes(parent->child(k), old_weights);
      volumes(parent, new_weights);
      range(children, old_weights, mean, lower, upper);

      CellValues          result(1, std::vector<double>(n_values * n_q, 0.));
      std::vector<double> weight(n_q, 0.);
      for (unsigned int k = 0; k < children.size(); ++k)
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const unsigned int p = nearest[k][q];
            const double       w = old_weights[k * n_q + q];
            weight[p] += w;
            for (unsigned int v = 0; v < n_values; ++v)
              result[0][v * n_q + p] += w * children[k][v * n_q + q];
          }
      for (unsigned int p = 0; p < n_q; ++p)
        for (unsigned int v = 0; v < n_values; ++v)
          result[0][v * n_q + p] =
            weight[p] > 0 ? result[0][v * n_q + p] / weight[p] : mean[v];
      limit(result, new_weights, mean, lower, upper);
      return result[0];
    }

    template <int dim>
    void HistoryTransfer<dim>::prepare(
      parallel::distributed::Triangulation<dim> &triangulation,
      state::HistoryStorage<dim>                &history)
    {
      tria                   = &triangulation;
      const unsigned int n_q = quadrature.size();
      // Per cell: the point values, value-major (n_values x n_q).
      old_values.assign(tria->n_active_cells(), {});
      std::vector<double> packed;
      for (const auto &cell : tria->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto data = history.get_data(cell);
            Assert(data.size() == n_q, ExcInternalError());
            auto &out = old_values[cell->active_cell_index()];
            out.resize(n_q * n_values);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                data[q]->pack_values(packed);
                for (unsigned int v = 0; v < n_values; ++v)
                  out[v * n_q + q] = packed[v];
              }
          }
      transfer = std::make_unique<
        parallel::distributed::CellDataTransfer<dim, dim, CellValues>>(
        *tria,
        /*variable size*/ false,
        [this](const CellIterator &parent, const std::vector<double> &values) {
          return refine(parent, values);
        },
        [this](const CellIterator &parent, const CellValues &children) {
          return coarsen(parent, children);
        });
      transfer->prepare_for_coarsening_and_refinement(old_values);
    }

    template <int dim>
    void HistoryTransfer<dim>::interpolate(state::HistoryStorage<dim> &history)
    {
      Assert(transfer, ExcInternalError());
      CellValues new_values(tria->n_active_cells());
      transfer->unpack(new_values);
      const unsigned int  n_q = quadrature.size();
      std::vector<double> point(n_values);
      for (const auto &cell : tria->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &in = new_values[cell->active_cell_index()];
            Assert(in.size() == n_q * n_values, ExcInternalError());
            const auto data = history.get_data(cell);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                for (unsigned int v = 0; v < n_values; ++v)
                  point[v] = in[v * n_q + q];
                data[q]->unpack_values(point);
              }
          }
      transfer.reset();
      old_values.clear();
    }

#define INSTANTIATE(dim) template class HistoryTransfer<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace refinement
} // namespace formsolve
