// Values of the earlier run's mesh at points of a trimmed part's new mesh
// (reference configuration), wherever on the ranks the points lie: deal.II's
// RemotePointEvaluation, one cell per point. Used by part_mesh.cc and
// part_transfer.cc.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <formsolve/state/state.h>

#include <limits>
#include <string>
#include <vector>

namespace formsolve
{
  namespace trimming
  {
    /// @p points (reference configuration) located in @p earlier's mesh;
    /// with @p what, throws naming Geometry/Start from if one lies outside
    /// it. Collective.
    template <int dim>
    void locate(const state::State<dim>                            &earlier,
                const std::vector<dealii::Point<dim>>              &points,
                dealii::Utilities::MPI::RemotePointEvaluation<dim> &cache,
                const char                                         *what)
    {
      cache.reinit(points, earlier.tria, earlier.reference_mapping);
      if (what == nullptr)
        return;
      unsigned int missing = 0;
      for (unsigned int i = 0; i < points.size(); ++i)
        missing += !cache.point_found(i);
      missing = dealii::Utilities::MPI::sum(missing, earlier.comm);
      AssertThrow(missing == 0,
                  dealii::ExcMessage("Geometry/Start from: " +
                                     std::to_string(missing) + " " + what +
                                     " of the trimmed part's mesh lie outside "
                                     "the earlier run's part"));
    }

    /// A value of the earlier cell holding each point of @p cache, by
    /// @p value(cell, unit point), in the order of the points (NaN where a
    /// point was not found). Collective.
    template <int dim, typename Value>
    std::vector<double>
    cell_values(const state::State<dim> &earlier,
                const dealii::Utilities::MPI::RemotePointEvaluation<dim> &cache,
                const Value                                              &value)
    {
      using Cell = typename dealii::Triangulation<dim>::active_cell_iterator;
      std::vector<double> out, buffer;
      cache.template evaluate_and_process<double>(
        out,
        buffer,
        [&](const dealii::ArrayView<double> &values, const auto &data) {
          for (unsigned int c = 0; c < data.cells.size(); ++c)
            {
              const Cell cell(&earlier.tria,
                              data.cells[c].first,
                              data.cells[c].second);
              for (unsigned int i = data.reference_point_ptrs[c];
                   i < data.reference_point_ptrs[c + 1];
                   ++i)
                values[i] = value(cell, data.reference_point_values[i]);
            }
        });
      const auto         &ptrs = cache.get_point_ptrs();
      std::vector<double> first(ptrs.size() - 1,
                                std::numeric_limits<double>::quiet_NaN());
      for (std::size_t p = 0; p + 1 < ptrs.size(); ++p)
        if (ptrs[p + 1] > ptrs[p])
          first[p] = out[ptrs[p]];
      return first;
    }
  } // namespace trimming
} // namespace formsolve
