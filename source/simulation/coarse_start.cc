#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/adaptation_strategies.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/refinement/adapt.h>
#include <formsolve/simulation/coarse_start.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    namespace
    {
      /// Mean over the locally owned active cells of the in-plane length
      /// (the geometric mean of the extents along the cells' in-plane
      /// directions; the last one is through the thickness, as the blank
      /// mesh is built), all ranks.
      template <int dim>
      double mean_in_plane_size(const State<dim> &state)
      {
        double       sum = 0;
        unsigned int n   = 0;
        for (const auto &cell : state.tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              double p = 1;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                p *= cell->extent_in_direction(d);
              sum += std::pow(p, 1. / (dim - 1));
              ++n;
            }
        const double total = Utilities::MPI::sum(sum, state.comm);
        const double cells = Utilities::MPI::sum(double(n), state.comm);
        return cells > 0 ? total / cells : 0;
      }
    } // namespace

    template <int dim>
    CoarseStartReport coarse_start(State<dim>                      &state,
                                   solver::StepSolver<dim>         &step_solver,
                                   const state::HistoryUpdate<dim> &update,
                                   const double                     max_dt,
                                   const std::function<void()>     &release)
    {
      Assert(state.step == 0, ExcMessage("only the first step starts at rest"));
      CoarseStartReport report;
      auto             &tria = state.tria;
      const auto       &prm  = state.prm;

      // A family coarsens into a cell twice as long: judge the coarser mesh
      // by twice the present size before changing anything.
      report.coarse_cell_size = 2 * mean_in_plane_size(state);
      const double limit =
        prm.nonlinear.coarse_cell_size_limit * prm.geometry.thickness;
      if (report.coarse_cell_size > limit)
        {
          std::ostringstream s;
          s << "the coarser cells would be " << report.coarse_cell_size
            << " mm long in the plane, above Nonlinear solver/Coarse cell "
               "size limit ("
            << limit << " mm)";
          report.reason = s.str();
          return report;
        }

      // Coarsen every complete family once. Each cell carries a 1; summed
      // over a family on coarsening, a value above 1 marks the cells to
      // refine again, so that the run's mesh comes back exactly.
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && cell->level() > 0)
          cell->set_coarsen_flag();
      Vector<float> ones(tria.n_active_cells()), merged;
      ones = 1.f;
      parallel::distributed::CellDataTransfer<dim, dim, Vector<float>> marks(
        tria,
        false,
        &AdaptationStrategies::Refinement::preserve<dim, dim, float>,
        &AdaptationStrategies::Coarsening::sum<dim, dim, float>);
      const auto coarsened = refinement::adapt_flagged(state, update, [&]() {
        if (release)
          release();
        marks.prepare_for_coarsening_and_refinement(ones);
      });
      if (!coarsened.changed)
        {
          report.reason = "no cell of the mesh can be coarsened";
          return report;
        }
      merged.reinit(tria.n_active_cells());
      marks.unpack(merged);
      step_solver.reinit();
      report.used        = true;
      report.coarse_dofs = state.dof_handler.n_dofs();

      report.step      = step_solver.solve(max_dt, true);
      report.converged = report.step.converged;
      if (!report.converged)
        report.reason = report.step.failure;

      // Back to the run's mesh. After a failed try the state is that of the
      // start of the step, at rest, as if nothing had been tried.
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            merged[cell->active_cell_index()] > 1.5f)
          cell->set_refine_flag();
      refinement::adapt_flagged(state, update, release);
      step_solver.reinit();
      Assert(tria.n_global_active_cells() == coarsened.cells_before,
             ExcMessage("the run's mesh did not come back"));
      return report;
    }

#define INSTANTIATE(dim)                                                     \
  template CoarseStartReport coarse_start(State<dim> &,                      \
                                          solver::StepSolver<dim> &,         \
                                          const state::HistoryUpdate<dim> &, \
                                          const double,                      \
                                          const std::function<void()> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
