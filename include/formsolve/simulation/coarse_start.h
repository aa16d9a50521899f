// The first step's start from a coarser mesh (nested iteration): the step
// is solved on the mesh one level coarser everywhere, and its solution,
// interpolated back onto the run's mesh, is where Newton starts there
// (doc/theory.md section 8a).
#pragma once

#include <formsolve/forming/step_solver.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>

#include <functional>
#include <string>

namespace formsolve
{
  namespace simulation
  {
    using state::State;
    using state::VectorType;

    struct CoarseStartReport
    {
      bool   used        = false; // a coarse solve ran
      bool   converged   = false; // and its solution is the start
      double coarse_dofs = 0;
      /// Mean in-plane cell length of the coarser mesh (mm).
      double             coarse_cell_size = 0;
      std::string        reason; // why it was not used, or how the solve failed
      solver::StepReport step;   // the coarse solve
    };

    /// Before the first step (the sheet at rest, nothing advanced yet):
    /// coarsens @p state's mesh one level wherever p4est can, solves the
    /// step of at most @p max_dt there as a trial of @p step_solver, and
    /// refines back to the same mesh, carrying velocity and contact state
    /// both ways. Skipped, leaving the state untouched, when the coarser
    /// cells would be longer on average than
    /// Nonlinear solver/Coarse cell size limit sheet thicknesses in the
    /// plane. @p release runs before each mesh change (frees the factors).
    template <int dim>
    CoarseStartReport coarse_start(State<dim>                      &state,
                                   solver::StepSolver<dim>         &step_solver,
                                   const state::HistoryUpdate<dim> &update,
                                   const double                     max_dt,
                                   const std::function<void()>     &release);
  } // namespace simulation
} // namespace formsolve
