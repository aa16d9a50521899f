// After the last step: the trim of the formed part (Trimming;
// doc/trimming.md), its files, screen line and summary lines.
#include <deal.II/base/mpi.h>

#include <formsolve/app/error_exit.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/simulation/time_loop.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    std::unique_ptr<model::CurrentMapping<dim>>
    TimeLoop<dim>::start_configuration() const
    {
      VectorType start(state.displacement);
      start.add(-last_dt, state.velocity);
      auto c = std::make_unique<model::CurrentMapping<dim>>(prm.mesh.degree);
      c->initialize(state.reference_mapping, state.dof_handler, start, true);
      return c;
    }

    template <int dim>
    void TimeLoop<dim>::trim()
    {
      const auto         t0 = std::chrono::steady_clock::now();
      TimerOutput::Scope scope(timer, "trimming");
      try
        {
          const trimming::TrimShape<dim> shape(prm.trimming,
                                               prm.geometry.model,
                                               comm);
          trimming::KeptCells            cells;
          const auto                     r = trimming::trim_part(state,
                                             shape,
                                             prm.trimming,
                                             history_update,
                                             cells);
          if (r.cells_after != r.cells_before)
            forces_current = false;
          AssertThrow(r.volume_kept > 0,
                      ExcMessage("the cuts of the Trimming subsection keep "
                                 "nothing of the part"));
          kept    = std::make_unique<trimming::KeptCells>(std::move(cells));
          trimmed = std::make_unique<trimming::TrimReport>(r);
          write_trimmed();
          std::ostringstream line;
          line << "trimming: kept " << r.cells_kept << " of " << r.cells_after
               << " cells (" << 100 * r.volume_kept / r.volume_before
               << " % of the volume); the cut edge lies within "
               << r.edge_deviation << " mm of the trim line after " << r.passes
               << " refinement pass(es)";
          if (r.volume_kept >= r.volume_before * (1 - 1e-12))
            line << "; the cuts remove nothing";
          pcout << line.str() << "\n";
        }
      catch (const std::exception &e)
        {
          trim_failure = app::exception_text(e);
          kept.reset();
          trimmed.reset();
          pcout << "trimming failed: " << trim_failure << "\n";
        }
      trim_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
    }

    template <int dim>
    void TimeLoop<dim>::write_trimmed()
    {
      state.velocity_ghost     = state.velocity;
      state.displacement_ghost = state.displacement;
      const model::MaterialFrame<dim> frame(material.rolling_direction());
      postprocess::OutputFields<dim>  f{&state.velocity_ghost,
                                       &state.displacement_ghost,
                                       {},
                                       &state.history,
                                       {},
                                       material.isotropic() ? nullptr : &frame};
      const auto                     &cells = *kept;
      writer->write_part(
        state.step,
        state.dof_handler,
        *state.mapping,
        f,
        [&cells](const auto &cell) { return cells[cell->active_cell_index()]; },
        "trimmed");
      // The cut edge: the centres of the faces between kept and cut-away
      // cells, by angle about the z axis (3-D) or along z (sections).
      const auto          mine = trimming::cut_faces(state, cells);
      std::vector<double> flat;
      for (const auto &p : mine)
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(p[d]);
      const auto all = Utilities::MPI::gather(comm, flat, 0);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::vector<Point<dim>> points;
      for (const auto &part : all)
        for (std::size_t i = 0; i + dim <= part.size(); i += dim)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = part[i + d];
            points.push_back(p);
          }
      const auto key = [](const Point<dim> &p) {
        return dim == 3 ? std::atan2(p[1], p[0]) : p[dim - 1];
      };
      std::sort(points.begin(),
                points.end(),
                [&](const auto &a, const auto &b) {
                  return key(a) < key(b) ||
                         (key(a) == key(b) && a[dim - 1] < b[dim - 1]);
                });
      postprocess::write_atomically(prm.output.directory + "/trim-outline.csv",
                                    [&](std::ostream &o) {
                                      const auto n = model::coordinate_names(
                                        prm.geometry.model);
                                      o.precision(10);
                                      for (unsigned int d = 0; d < dim; ++d)
                                        o << (d ? "," : "") << n[d];
                                      o << '\n';
                                      for (const auto &p : points)
                                        for (unsigned int d = 0; d < dim; ++d)
                                          o << p[d]
                                            << (d + 1 < dim ? ',' : '\n');
                                    });
    }

    template <int dim>
    std::string TimeLoop<dim>::trimming_summary() const
    {
      if (!prm.trimming.any())
        return "";
      std::ostringstream f;
      f.precision(8);
      f << "\ntrimming = "
        << (trimmed                ? "done"
            : trim_failure.empty() ? "not run"
                                   : "failed")
        << "\ntrimming_failure = " << trim_failure
        << "\ntrimming_wall_time = " << trim_seconds;
      if (!trimmed)
        return f.str();
      const auto  &r = *trimmed;
      const double full =
        r.volume_kept * model::symmetry_factor(prm.geometry.model);
      f << "\ntrimming_passes = " << r.passes
        << "\ntrimming_edge_deviation = " << r.edge_deviation
        << "\ntrimming_cells_kept = " << r.cells_kept
        << "\ntrimming_cells = " << r.cells_after
        << "\ntrimming_volume = " << r.volume_kept
        << "\ntrimming_volume_fraction = " << r.volume_kept / r.volume_before
        << "\ntrimming_strain_integral = " << r.strain_kept
        << "\ntrimming_part_volume = " << full;
      if (std::isfinite(prm.material.density))
        f << "\ntrimming_part_mass = " << full * prm.material.density * 1e-6;
      return f.str();
    }

#define INSTANTIATE(dim)                                           \
  template std::unique_ptr<model::CurrentMapping<dim>>             \
                       TimeLoop<dim>::start_configuration() const; \
  template void        TimeLoop<dim>::trim();                      \
  template void        TimeLoop<dim>::write_trimmed();             \
  template std::string TimeLoop<dim>::trimming_summary() const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
