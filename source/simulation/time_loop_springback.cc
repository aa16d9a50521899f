// After the last step: the springback release of the formed part
// (Springback/Enabled; doc/springback.md), its file, screen lines, summary
// lines and warnings.
#include <deal.II/base/mpi.h>

#include <formsolve/app/error_exit.h>
#include <formsolve/model/current_mapping.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/simulation/time_loop.h>
#include <formsolve/springback/measure_points.h>
#include <formsolve/springback/section_profile.h>
#include <formsolve/springback/springback_output.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    void TimeLoop<dim>::spring_back()
    {
      const auto         t0 = std::chrono::steady_clock::now();
      TimerOutput::Scope scope(timer, "springback");
      try
        {
          const material::ReleaseLaw law(prm.material);
          // The configuration where the last step found its equilibrium
          // (its start): the stress there is the one the tools balanced,
          // while on the current mesh the last velocity no longer matches
          // elements that turned during the step (around a die radius).
          const auto configuration = start_configuration();
          // The forces the tools balanced at the last converged step, unless
          // the mesh changed since; a trimmed part releases its own end
          // stress.
          springback::Release<dim> release(
            state,
            *configuration,
            material,
            law,
            forces_current ? &step_solver.forming_system().body_forces()
                           : nullptr,
            kept.get());
          const auto s = release.solve();
          springback::write_sprung_part(release, state, prm.output.directory);
          sprung_shape = std::make_unique<VectorType>(
            springback::sprung_displacement(release, state));
          measure_section(release);
          at_points = springback::springback_at(release,
                                                state,
                                                prm.springback.measure_points);
          write_points();
          if (prm.springback.slit)
            opening = std::make_unique<springback::RingOpening>(
              springback::ring_opening(release, *configuration));
          released = std::make_unique<springback::ReleaseSummary>(s);
          pcout << "springback: released " << s.released_force
                << " N of internal force in " << s.iterations
                << " iteration(s); largest displacement component "
                << s.max_displacement << " mm; yields again in "
                << 100 * s.yielded_fraction << " % of the volume; held "
                << s.supports << "\n";
          if (opening)
            pcout << "split ring: opening " << opening->mean << " mm (from "
                  << opening->low << " to " << opening->high
                  << " mm over the slit's " << opening->nodes << " nodes)\n";
        }
      catch (const std::exception &e)
        {
          springback_failure = app::exception_text(e);
          pcout << "springback failed: " << springback_failure << "\n";
        }
      springback_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
      pcout << std::flush;
    }

    template <int dim>
    void TimeLoop<dim>::measure_section(const springback::Release<dim> &release)
    {
      auto profile = springback::section_profile(release, state);
      if (profile.empty())
        return;
      std::sort(profile.begin(),
                profile.end(),
                [](const auto &a, const auto &b) { return a.X0 < b.X0; });
      const auto n = model::coordinate_names(prm.geometry.model);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        postprocess::write_atomically(prm.output.directory +
                                        "/springback-profile.csv",
                                      [&](std::ostream &f) {
                                        f.precision(10);
                                        f << n[0] << "0," << n[0] << "_end,"
                                          << n[1] << "_end," << n[0]
                                          << "_sprung," << n[1] << "_sprung\n";
                                        for (const auto &p : profile)
                                          f << p.X0 << ',' << p.end[0] << ','
                                            << p.end[1] << ',' << p.sprung[0]
                                            << ',' << p.sprung[1] << '\n';
                                      });
      const auto &t = prm.tools;
      if (prm.geometry.model != model::Model::plane_strain ||
          !t.punch.enabled || !t.die.enabled ||
          t.punch.shape != parameters::ToolShape::round ||
          t.die.shape != parameters::ToolShape::round)
        return;
      const springback::ChannelTools tools{0.5 * t.punch.diameter,
                                           t.punch.profile_radius,
                                           0.5 * t.die.diameter,
                                           t.die.profile_radius};
      channel = std::make_unique<std::array<springback::ChannelMeasures, 2>>(
        std::array<springback::ChannelMeasures, 2>{
          {springback::channel_measures(profile, tools, false),
           springback::channel_measures(profile, tools, true)}});
      const auto &[before, after] = *channel;
      if (std::isnan(after.theta1))
        pcout << "channel: no angles: bottom, wall and flange have "
              << after.bottom << ", " << after.wall << " and " << after.flange
              << " mid-surface nodes, fewer than 3 in one (a short draw)\n";
      else
        pcout << "channel: bottom-wall angle " << before.theta1 << " -> "
              << after.theta1 << " deg, wall-flange angle " << before.theta2
              << " -> " << after.theta2 << " deg, wall curl radius "
              << before.rho << " -> " << after.rho << " mm\n";
    }

    template <int dim>
    void TimeLoop<dim>::write_points() const
    {
      if (at_points.empty() || Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      postprocess::write_atomically(
        prm.output.directory + "/springback-points.csv",
        [&](std::ostream &f) {
          const auto n = model::coordinate_names(prm.geometry.model);
          f.precision(10);
          f << "point";
          for (const std::string what : {"", "normal_", "displacement_"})
            for (unsigned int d = 0; d < dim; ++d)
              f << ',' << what << n[d];
          f << ",normal_displacement\n";
          for (std::size_t k = 0; k < at_points.size(); ++k)
            {
              const auto &p = at_points[k];
              f << k + 1;
              for (const auto *v : {&p.node, &p.normal, &p.displacement})
                for (unsigned int d = 0; d < dim; ++d)
                  f << ',' << (*v)[d];
              f << ',' << p.along_normal << '\n';
            }
        });
    }

    template <int dim>
    std::string TimeLoop<dim>::springback_summary() const
    {
      if (!prm.springback.enabled)
        return "";
      std::ostringstream f;
      f.precision(8);
      f << "\nspringback = "
        << (released                     ? "done"
            : springback_failure.empty() ? "not run"
                                         : "failed")
        << "\nspringback_failure = " << springback_failure
        << "\nspringback_wall_time = " << springback_seconds;
      if (!released)
        return f.str();
      const auto &s = *released;
      f << "\nspringback_iterations = " << s.iterations
        << "\nspringback_released_force = " << s.released_force
        << "\nspringback_residual = " << s.residual
        << "\nspringback_imbalance = " << s.imbalance << "\nspringback_load = "
        << (kept             ? "end stress of the trimmed part"
            : forces_current ? "tool forces"
                             : "end stress")
        << "\nspringback_max_displacement = " << s.max_displacement
        << "\nspringback_yielded_fraction = " << s.yielded_fraction
        << "\nspringback_max_trial_ratio = " << s.max_trial_ratio
        << "\nspringback_max_plastic_strain = " << s.max_plastic_strain
        << "\nspringback_small_strain_fraction = " << s.small_strain_fraction
        << "\nspringback_rigid_fraction = " << s.rigid_fraction
        << "\nspringback_supports = " << s.supports;
      for (std::size_t k = 0; k < at_points.size(); ++k)
        f << "\nspringback_normal_" << k + 1 << " = "
          << at_points[k].along_normal;
      if (opening)
        f << "\nring_opening = " << opening->mean
          << "\nring_opening_min = " << opening->low
          << "\nring_opening_max = " << opening->high
          << "\nring_slit_nodes = " << opening->nodes;
      if (channel)
        {
          const auto &[before, after] = *channel;
          f << "\nchannel_theta1_end = " << before.theta1
            << "\nchannel_theta1 = " << after.theta1
            << "\nchannel_theta2_end = " << before.theta2
            << "\nchannel_theta2 = " << after.theta2
            << "\nchannel_rho_end = " << before.rho
            << "\nchannel_rho = " << after.rho
            << "\nchannel_points = " << after.bottom << ' ' << after.wall << ' '
            << after.flange;
        }
      return f.str();
    }

    template <int dim>
    std::vector<std::string> TimeLoop<dim>::springback_warnings() const
    {
      std::vector<std::string> w;
      if (!released)
        return w;
      const auto        &s     = *released;
      const double       limit = prm.springback.unsound_volume_warning;
      std::ostringstream text;
      text.precision(3);
      if (s.small_strain_fraction > limit)
        text << "springback: " << 100 * s.small_strain_fraction
             << " % of the volume has less plastic strain than "
             << prm.springback.sound_strain_ratio
             << " yield strains; there the rigid-plastic end stress is not "
                "what an elasto-plastic forming leaves, and its springback "
                "is not reliable (doc/theory.md, section 12)";
      if (!text.str().empty())
        w.push_back(text.str());
      text.str("");
      if (s.rigid_fraction > limit)
        text << "springback: " << 100 * s.rigid_fraction
             << " % of the volume was rigid in the last step; there the "
                "flow rule leaves the stress to equilibrium alone, so the "
                "residual stresses written there (and whether they yield "
                "again) are not an elasto-plastic forming's; where nothing "
                "yields again the sprung shape does not depend on them, it "
                "follows from the tools' forces (doc/theory.md, section 12)";
      if (!text.str().empty())
        w.push_back(text.str());
      text.str("");
      if (s.yielded_fraction > 0)
        text << "springback: the release yields again in "
             << 100 * s.yielded_fraction << " % of the volume (trial "
             << "equivalent stress up to " << s.max_trial_ratio
             << " times the yield stress); corrected by the elasto-plastic "
                "release, plastic strain up to "
             << s.max_plastic_strain;
      if (!text.str().empty())
        w.push_back(text.str());
      return w;
    }

#define INSTANTIATE(dim)                                                       \
  template void                     TimeLoop<dim>::spring_back();              \
  template std::string              TimeLoop<dim>::springback_summary() const; \
  template std::vector<std::string> TimeLoop<dim>::springback_warnings() const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
