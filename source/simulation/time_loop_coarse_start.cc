// TimeLoop: the first step started from the coarser mesh (Nonlinear
// solver/First step start; simulation/coarse_start.h does the work).
#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/coarse_start.h>
#include <formsolve/simulation/time_loop.h>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    void TimeLoop<dim>::start_from_coarser_mesh(RunSummary &summary)
    {
      const double start = seconds();
      auto         r =
        coarse_start(state,
                     step_solver,
                     history_update,
                     (state.tools.punch_stroke() - state.tools.punch_travel()) /
                       state.tools.punch_speed(),
                     [this]() { step_solver.release_factors(); });
      summary.newton_wall_time += seconds() - start;
      summary.coarse_start_iterations = r.step.iterations;
      if (r.used)
        pcout << "first step on the coarser mesh ("
              << static_cast<unsigned long>(r.coarse_dofs)
              << " DoFs): " << r.step.iterations << " Newton iterations"
              << (r.converged ? "; its solution is the start"
                              : ", not converged (" + r.reason +
                                  "); the first step starts from rest")
              << std::endl;
      else
        pcout << "first step from rest: " << r.reason << std::endl;
    }

#define INSTANTIATE(dim) \
  template void TimeLoop<dim>::start_from_coarser_mesh(RunSummary &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
