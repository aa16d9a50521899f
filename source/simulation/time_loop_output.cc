// The time loop's VTU output: the sheet with its fields, and the tools.
#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/time_loop.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    void TimeLoop<dim>::write_output(const bool last)
    {
      const bool section  = last_output_step != int(state.step);
      const bool revolved = dim == 2 && prm.output.revolved_copy &&
                            (prm.output.revolved_every_output ? section : last);
      if (!section && !revolved)
        return;
      TimerOutput::Scope t(timer, "output");
      // Output and checkpoints build buffers of the size of the state: free
      // the factors first, so that they do not add to the run's peak.
      step_solver.release_factors();
      state.velocity_ghost = state.velocity;
      contact_fields.fill(state,
                          step_solver.forming_system().penalty_factors(),
                          prm.contact.search_distance);
      sheet.measure(state, damage);
      // sheet.csv at every output step: after an error on several ranks,
      // which allows no collective call, the last one stays.
      sheet.write_csv(comm, prm.output.directory);
      auto nodal = contact_fields.scalars();
      for (const auto &f : sheet.nodal_fields(state))
        nodal.push_back(f);
      const model::MaterialFrame<dim> frame(material.rolling_direction());
      column_damage.measure(state, damage, true);
      postprocess::OutputFields<dim> f{
        &state.velocity_ghost,
        &state.displacement_ghost,
        nodal,
        &state.history,
        {{damage.criterion() == parameters::FractureCriterion::cockcroft_latham
            ? "cockcroft_latham_through_thickness"
            : "oyane_through_thickness",
          &column_damage.cell_values()}},
        material.isotropic() ? nullptr : &frame};
      writer->write(state.step,
                    state.time,
                    state.dof_handler,
                    *state.mapping,
                    f,
                    section,
                    revolved);
      if (section)
        tool_writer->write(state.step,
                           state.time,
                           state.tools,
                           tool_extent(),
                           prm.tools.draw_beads,
                           prm.geometry.thickness,
                           comm);
      last_output_step = state.step;
    }

    template <int dim>
    tools::SurfaceExtent TimeLoop<dim>::tool_extent() const
    {
      // The faces reach 10 mm past the blank's reference outline, the walls
      // over the punch stroke and 10 mm more.
      double reach = 0;
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            {
              const Point<dim> &x = cell->vertex(v);
              reach = std::max(reach, dim == 2 ? x[0] : std::hypot(x[0], x[1]));
            }
      tools::SurfaceExtent e;
      e.reach = Utilities::MPI::max(reach, comm) + 10;
      e.wall  = state.tools.punch_stroke() + 10;
      switch (prm.geometry.model)
        {
          case model::Model::half:
            e.first_angle = -90, e.last_angle = 90;
            break;
          case model::Model::full:
            e.first_angle = 0, e.last_angle = 360;
            break;
          default: // quarter (and the axisymmetric section, which ignores it)
            e.first_angle = 0, e.last_angle = 90;
        }
      return e;
    }

#define INSTANTIATE(dim)                                                 \
  template void                 TimeLoop<dim>::write_output(const bool); \
  template tools::SurfaceExtent TimeLoop<dim>::tool_extent() const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
