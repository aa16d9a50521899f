// Quadrature history across refinement and coarsening of a distributed mesh.
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/model/kinematics.h>
#include <formsolve/state/quadrature_history.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace refinement
  {
    /// Carries every history value's quadrature-point values to the new
    /// cells (doc/theory.md, section 7a). A point stands for the part of its
    /// cell nearest to it: a refined cell's children copy, at each of their
    /// points, the value of the parent's point nearest to it; a coarsened
    /// family gives each of the parent's points the volume-weighted mean of
    /// the children's points nearest to it. Every new value lies within the
    /// range of the values it came from, so no new maximum is made (a
    /// polynomial projection overshoots, a limited one smooths: a damage
    /// maximum could cross 1 at an adaptation) and a peak is not smoothed away;
    /// the family's integral in the reference configuration is then made exact
    /// by moving the values towards the family's mean by as little as it takes.
    template <int dim>
    class HistoryTransfer
    {
    public:
      /// @p mapping and @p kinematics give the volume elements of the
      /// reference configuration.
      HistoryTransfer(const dealii::Quadrature<dim> &quadrature,
                      const dealii::Mapping<dim>    &mapping,
                      const model::Kinematics<dim>  &kinematics);

      /// Before tria.execute_coarsening_and_refinement() (collective).
      void prepare(dealii::parallel::distributed::Triangulation<dim> &tria,
                   state::HistoryStorage<dim>                        &history);

      /// After it, with @p history initialised on the new locally owned
      /// cells.
      void interpolate(state::HistoryStorage<dim> &history);

    private:
      using CellValues   = std::vector<std::vector<double>>;
      using CellIterator = typename dealii::Triangulation<dim>::cell_iterator;

      /// Values of @p parent's children (each n_values x n_q, value-major)
      /// after refinement.
      CellValues refine(const CellIterator        &parent,
                        const std::vector<double> &values);
      /// The parent's values after coarsening its @p children.
      std::vector<double> coarsen(const CellIterator &parent,
                                  const CellValues   &children);
      /// Volume elements of @p cell's quadrature points (reference
      /// configuration), appended to @p weights.
      void volumes(const CellIterator &cell, std::vector<double> &weights);

      /// Per value: the mean weighted by @p weights (all points of
      /// @p cells in order), the minimum and the maximum.
      void range(const CellValues          &cells,
                 const std::vector<double> &weights,
                 std::vector<double>       &mean,
                 std::vector<double>       &lower,
                 std::vector<double>       &upper) const;
      /// Shifts the values of @p cells to the weighted @p mean and scales
      /// their deviation from it until each lies in [lower, upper] (by one
      /// factor for the family, which keeps the mean).
      void limit(CellValues                &cells,
                 const std::vector<double> &weights,
                 const std::vector<double> &mean,
                 const std::vector<double> &lower,
                 const std::vector<double> &upper) const;

      const dealii::FE_Nothing<dim> fe;
      const dealii::Quadrature<dim> quadrature;
      /// [child][child's point]: the parent's point nearest to it.
      std::vector<std::vector<unsigned int>>             nearest;
      const model::Kinematics<dim>                      &kinematics;
      dealii::FEValues<dim>                              fe_values;
      unsigned int                                       n_values = 0;
      dealii::parallel::distributed::Triangulation<dim> *tria     = nullptr;
      CellValues                                         old_values;
      std::unique_ptr<
        dealii::parallel::distributed::CellDataTransfer<dim, dim, CellValues>>
        transfer;
    };
  } // namespace refinement
} // namespace formsolve
