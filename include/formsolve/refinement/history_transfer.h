// Quadrature history across refinement and coarsening of a distributed mesh.
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/lac/full_matrix.h>

#include <formsolve/simulation/quadrature_history.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace refinement
  {
    /// Every history value is L2-projected per cell onto discontinuous Q_p;
    /// a refined cell gives each child the parent's polynomial (FE_DGQ's
    /// prolongation), a coarsened family gives the parent the L2 projection
    /// of the children's (FE_DGQ's restriction, summed over the children);
    /// the new cells evaluate it at their quadrature points. Cell integrals
    /// of every value are kept whenever a constant is in the projection
    /// space. deal.II 9.4's ContinuousQuadratureDataTransfer does the same
    /// for refinement but does not implement coarsening (its debug build
    /// asserts), hence this class on top of CellDataTransfer.
    template <int dim>
    class HistoryTransfer
    {
    public:
      HistoryTransfer(const unsigned int             degree,
                      const dealii::Quadrature<dim> &quadrature);

      /// Before tria.execute_coarsening_and_refinement() (collective).
      void prepare(dealii::parallel::distributed::Triangulation<dim> &tria,
                   simulation::HistoryStorage<dim>                   &history);

      /// After it, with @p history initialised on the new locally owned
      /// cells.
      void interpolate(simulation::HistoryStorage<dim> &history);

    private:
      using CellValues = std::vector<std::vector<double>>;

      const dealii::FE_DGQ<dim>                          fe;
      const dealii::Quadrature<dim>                      quadrature;
      dealii::FullMatrix<double>                         to_fe, to_points;
      unsigned int                                       n_values = 0;
      dealii::parallel::distributed::Triangulation<dim> *tria     = nullptr;
      CellValues                                         old_values;
      std::unique_ptr<
        dealii::parallel::distributed::CellDataTransfer<dim, dim, CellValues>>
        transfer;
    };
  } // namespace refinement
} // namespace formsolve
