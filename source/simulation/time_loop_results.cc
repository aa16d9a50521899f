// The forming results of the time loop: what is measured every step
// (thickness, strains, zones, draw-in, damage), the critical stroke, the run
// summary and the report.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/beads/bead_operator.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/parameters/plausibility.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/simulation/time_loop.h>
#include <formsolve/state/sheet_integrals.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <tuple>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;
    using Field = state::QuadraturePointHistory;

    namespace
    {
      /// formsolve-report next to the running binary (the build tree and an
      /// installed bin/ both keep it there); empty if it is not there.
      std::string report_tool()
      {
        char          exe[PATH_MAX];
        const ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
        if (n <= 0)
          return "";
        std::string path(exe, n);
        path = path.substr(0, path.rfind('/') + 1) + "formsolve-report";
        return access(path.c_str(), X_OK) == 0 ? path : "";
      }

      template <int dim>
      std::string where(const Point<dim> &x, const model::Model m)
      {
        const auto         names = model::coordinate_names(m);
        std::ostringstream s;
        for (unsigned int d = 0; d < dim; ++d)
          s << (d > 0 ? ", " : "") << names[d] << " = " << x[d];
        s << " mm";
        return s.str();
      }

      std::string criterion_name(const parameters::FractureCriterion c)
      {
        return c == parameters::FractureCriterion::oyane
                 ? "Oyane's integral"
                 : "the Cockcroft-Latham criterion";
      }
    } // namespace

    template <int dim>
    postprocess::FormingMeasures<dim> TimeLoop<dim>::measure_forming()
    {
      TimerOutput::Scope                t(timer, "forming results");
      postprocess::FormingMeasures<dim> m;
      sheet.measure(state, damage);
      m.sheet            = sheet.summary();
      m.oyane            = maximum(state, &Field::oyane);
      m.cockcroft_latham = maximum(state, &Field::cockcroft_latham);
      m.cockcroft_latham_ratio =
        damage.cockcroft_latham(m.cockcroft_latham.value);
      m.through_thickness = column_damage.measure(state, damage, false);
      return m;
    }

    template <int dim>
    postprocess::SplitEvent<dim>
    TimeLoop<dim>::check_fracture(const postprocess::FormingMeasures<dim> &m,
                                  RunSummary &summary)
    {
      postprocess::SplitEvent<dim> event;
      const auto                   criterion = damage.criterion();
      if (criterion == parameters::FractureCriterion::none)
        return event;
      const bool   oyane  = criterion == parameters::FractureCriterion::oyane;
      const double travel = state.tools.punch_travel();
      const auto  &c      = m.through_thickness;
      const std::array<std::tuple<RunSummary::Watch *,
                                  double,
                                  Point<dim>,
                                  parameters::FractureMeasure,
                                  const char *>,
                       2>
        measures{{{&summary.local,
                   oyane ? m.oyane.value : m.cockcroft_latham_ratio,
                   oyane ? m.oyane.location : m.cockcroft_latham.location,
                   parameters::FractureMeasure::local,
                   "its local maximum"},
                  {&summary.through_thickness,
                   oyane ? c.oyane.value : c.cockcroft_latham.value,
                   oyane ? c.oyane.location : c.cockcroft_latham.location,
                   parameters::FractureMeasure::through_thickness,
                   "its average through the thickness"}}};
      for (const auto &[w, value, location, measure, name] : measures)
        {
          if (w->stroke < 0 && value >= 1)
            {
              // Linear in the punch travel between the two steps.
              w->stroke = w->last_travel + (1 - w->last) / (value - w->last) *
                                             (travel - w->last_travel);
              std::ostringstream s;
              for (unsigned int d = 0; d < dim; ++d)
                s << (d ? " " : "") << location[d];
              w->location         = s.str();
              const bool deciding = measure == prm.material.fracture_measure;
              pcout << (deciding ? "fracture predicted: " : "note: ")
                    << criterion_name(criterion) << " reaches 1 by " << name
                    << " at punch travel " << w->stroke << " mm, at "
                    << where(location, prm.geometry.model)
                    << (deciding ? "" : " (not the deciding measure)")
                    << std::endl;
              if (deciding)
                {
                  summary.critical_stroke   = w->stroke;
                  summary.fracture_location = w->location;
                  event.travel              = w->stroke;
                  event.location            = location;
                  event.value               = value;
                  // The point's reference position is not kept.
                  event.reference_radius =
                    std::numeric_limits<double>::quiet_NaN();
                }
            }
          w->last        = value;
          w->last_travel = travel;
        }
      return event;
    }

    template <int dim>
    void TimeLoop<dim>::measure_memory(RunSummary &summary) const
    {
      Utilities::System::MemoryStats mem;
      Utilities::System::get_memory_stats(mem);
      summary.peak_memory_kb = Utilities::MPI::sum(double(mem.VmHWM), comm);
      summary.peak_memory_kb_max_rank =
        Utilities::MPI::max(double(mem.VmHWM), comm);
      const auto &local    = material.local_solves();
      summary.local_solves = Utilities::MPI::sum(double(local.solves), comm);
      summary.local_iterations =
        Utilities::MPI::sum(double(local.iterations), comm);
      summary.local_long_solves =
        Utilities::MPI::sum(double(local.long_solves), comm);
      summary.local_most_iterations =
        Utilities::MPI::max(double(local.most), comm);
    }

    namespace
    {
      /// The run summary's lines on the yield criterion: its name and
      /// directional values; for a non-quadratic one also the local solves
      /// (doc/theory.md, eq. 3e) and the fit to test data (eq. 3g).
      std::string criterion_lines(const parameters::Anisotropy      &a,
                                  const material::RigidViscoplastic &law,
                                  const RunSummary                  &summary)
      {
        std::ostringstream s;
        s << "\nyield_criterion = " << a.describe() << "\n"
          << law.criterion_summary();
        if (const auto *f = law.non_quadratic())
          {
            s << "\nlocal_newton_solves = " << summary.local_solves
              << "\nlocal_newton_mean_iterations = "
              << summary.local_iterations / std::max(1., summary.local_solves)
              << "\nlocal_newton_most_iterations = "
              << summary.local_most_iterations
              << "\nlocal_newton_over_6_iterations = "
              << summary.local_long_solves;
            if (!f->fit_lines().empty())
              s << "\n" << f->fit_lines();
          }
        return s.str();
      }
    } // namespace

    template <int dim>
    void TimeLoop<dim>::write_summary(const RunSummary &summary) const
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      const auto &sh = sheet.summary();
      // Machine-readable totals for benchmarks and the report.
      std::ostringstream f;
      f << "model = " << model::name(prm.geometry.model)
        << "\nsection_width = " << prm.geometry.section_depth()
        << summary_lines(earlier.get())
        << "\nranks = " << Utilities::MPI::n_mpi_processes(comm)
        << "\ndofs = " << summary.n_dofs
        << "\nmean_dofs = " << summary.dof_steps / std::max(1u, summary.steps)
        << "\ncells = " << state.tria.n_global_active_cells()
        << "\nsteps = " << summary.steps
        << "\nnewton_iterations = " << summary.newton_iterations
        << "\ncoarse_start_iterations = " << summary.coarse_start_iterations
        << "\nlinear_iterations = " << summary.linear_iterations
        << "\nmatrix_assemblies = " << summary.matrix_assemblies
        << "\nfactorisations = " << summary.factorisations
        << "\nfactorisation_memory_mb = " << summary.factorisation_memory_mb
        << "\nfactor_entries = " << summary.factor_entries
        << "\ncutbacks = " << summary.cutbacks
        << "\nwall_time = " << summary.wall_time
        << "\nnewton_wall_time = " << summary.newton_wall_time
        << "\npeak_memory_kb_all_ranks = " << summary.peak_memory_kb
        << "\npeak_memory_kb_max_rank = " << summary.peak_memory_kb_max_rank
        << "\nsetup_memory_kb_max_rank = " << summary.setup_memory_kb_max_rank
        << "\nfinal_punch_travel = " << state.tools.punch_travel()
        << "\nholder_release_travel = " << state.holder.release_travel
        << "\npeak_punch_force = " << summary.peak_punch_force
        << "\npeak_force_travel = " << summary.peak_force_travel
        << "\nmax_penetration = " << summary.max_penetration
        << "\nmin_thickness = " << sh.min_thickness
        << "\nmin_thickness_R0 = " << sh.min_thickness_radius
        << "\nmin_thickness_location = " << sh.min_thickness_location
        << (dim == 3
              ? "\nmin_thickness_angle = " +
                  std::to_string(std::atan2(sh.min_thickness_location[1],
                                            sh.min_thickness_location[0]) *
                                 180 / M_PI)
              : std::string())
        << "\nmax_thinning_percent = " << sh.max_thinning
        << criterion_lines(prm.material.anisotropy, material, summary)
        << "\nfracture_constants_conversion_k = " << damage.conversion()
        << "\noyane_a_used = " << damage.a_used()
        << "\noyane_b_used = " << damage.b_used() << "\nfracture_criterion = "
        << (damage.criterion() == parameters::FractureCriterion::oyane ? "oyane"
            : damage.criterion() == parameters::FractureCriterion::none
              ? "none"
              : "cockcroft-latham")
        << "\nfracture_measure = "
        << (prm.material.fracture_measure == parameters::FractureMeasure::local
              ? "local"
              : "through-thickness average")
        << "\ncritical_stroke = " << summary.critical_stroke
        << "\nfracture_location = " << summary.fracture_location
        << "\ncritical_stroke_local = " << summary.local.stroke
        << "\nfracture_location_local = " << summary.local.location
        << "\ncritical_stroke_through_thickness = "
        << summary.through_thickness.stroke
        << "\nfracture_location_through_thickness = "
        << summary.through_thickness.location
        << "\nforming_limit = " << sheet.forming_limit().source()
        << "\nflc0 = " << sheet.forming_limit().plane_strain_limit()
        << "\nsafety_margin = " << prm.material.safety_margin
        << "\nsevere_thinning = " << prm.material.severe_thinning
        << "\ninsufficient_stretch = " << prm.material.insufficient_stretch
        << "\nflc_margin_percent = " << sh.flc_margin;
      for (unsigned int z = 0; z < material::n_safety_zones; ++z)
        f << "\ncolumns_" << material::zone_key(material::SafetyZone(z))
          << " = " << sh.zone_count[z];
      f << split_summary() << trimming_summary() << springback_summary()
        << bead_summary();
      if (!earing.angle.empty())
        {
          f << "\ncup_height_mean = " << earing.mean
            << "\nearing_amplitude = " << earing.amplitude
            << "\nears = " << earing.ears << "\near_angles =";
          for (const double a : earing.ear_angles)
            f << ' ' << a;
        }
      f << "\nblank_holder_force = " << prm.tools.holder_force.at(0)
        << (prm.tools.holder_force.varies()
              ? "\nblank_holder_force_curve = " + prm.tools.holder_force.text()
              : "")
        << "\nironing_travel = " << summary.ironing_travel
        << "\nmax_ironing_force = " << summary.max_ironing_force
        << "\nmax_ironing_pressure = " << summary.max_ironing_pressure;
      auto warnings = parameters::plausibility_warnings(prm);
      for (const auto &w : scene_warnings)
        warnings.push_back(w);
      for (const auto &w : run_warnings())
        warnings.push_back(w);
      f << "\nwarnings = " << warnings.size();
      for (std::size_t k = 0; k < warnings.size(); ++k)
        f << "\nwarning_" << k + 1 << " = " << warnings[k];
      f << "\nend_reason = " << summary.end_reason << "\n";
      postprocess::write_atomically(prm.output.directory + "/run-summary.txt",
                                    [&](std::ostream &o) { o << f.str(); });
    }

    template <int dim>
    std::string TimeLoop<dim>::bead_summary() const
    {
      if (!prm.tools.draw_beads.any())
        return "";
      return beads::BeadOperator<dim>(prm, material, state.kinematics)
        .summary_lines(state.beads, prm.geometry.symmetry_factor());
    }

    template <int dim>
    std::string TimeLoop<dim>::split_summary() const
    {
      // -1: not met (machine-readable; the report says it in words).
      std::ostringstream f;
      f.precision(8);
      const bool  split_ = split.split();
      const auto &e      = split.first();
      f << "\nsplit = " << (split_ ? "yes" : "no")
        << "\nsplit_travel = " << (split_ ? e.travel : -1.)
        << "\nsplit_measure = "
        << (split_ ? postprocess::split_measure_name(split.split_measure())
                   : std::string("none"))
        << "\nsplit_location = "
        << (split_ ? e.where(prm.geometry.model) : std::string());
      // The same as numbers: the column's planform position (R0, angle from
      // x) and its current mid-surface point (NaN: not known / no split).
      const double nan = std::numeric_limits<double>::quiet_NaN();
      f << "\nsplit_R0 = " << (split_ ? e.reference_radius : nan)
        << "\nsplit_angle = " << (split_ ? e.reference_angle : nan);
      const auto names = model::coordinate_names(prm.geometry.model);
      for (unsigned int d = 0; d < dim; ++d)
        f << "\nsplit_" << names[d] << " = " << (split_ ? e.location[d] : nan);
      for (const auto m : {postprocess::SplitMeasure::forming_limit,
                           postprocess::SplitMeasure::neck,
                           postprocess::SplitMeasure::fracture})
        {
          std::string key = postprocess::split_measure_name(m);
          std::replace(key.begin(), key.end(), ' ', '_');
          const auto &ev = split.event(m);
          f << "\n"
            << key << "_travel = " << ev.travel << "\n"
            << key << "_location = "
            << (ev.met() ? ev.where(prm.geometry.model) : std::string());
        }
      f << "\nsplit_measures ="
        << (prm.split.by_forming_limit ? " forming_limit" : "")
        << (prm.split.by_neck ? " neck" : "")
        << (prm.split.by_fracture ? " fracture_criterion" : "");
      return f.str();
    }

    template <int dim>
    std::vector<std::string> TimeLoop<dim>::run_warnings() const
    {
      std::vector<std::string> w;
      for (unsigned int t = 0; t < tool_loaded.size(); ++t)
        if (!tool_loaded[t])
          w.push_back("Tools/" + state.tools[t].name() +
                      ": the tool never touched the sheet (its force stayed "
                      "0 over the run); check its position and stroke "
                      "against the blank");
      for (const auto &s : springback_warnings())
        w.push_back(s);
      if (earlier && !earlier->split.empty())
        w.push_back("Geometry/Start from: the part of " + earlier->folder +
                    " had split in that run (" + earlier->split +
                    "); this run formed a split part further");
      if (earlier && !earlier->trim_failure.empty())
        w.push_back("Geometry/Start from: the trimming of " + earlier->folder +
                    " failed (" + earlier->trim_failure +
                    "); this run formed the untrimmed part");
      return w;
    }

    template <int dim>
    void TimeLoop<dim>::make_report() const
    {
      if (!report_due || !prm.output.report ||
          Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      const std::string &dir  = prm.output.directory;
      const std::string  tool = report_tool();
      if (tool.empty())
        {
          std::cerr << "formsolve: warning: no run report (formsolve-report "
                       "is not next to the formsolve binary); run "
                       "formsolve-report "
                    << dir << std::endl;
          return;
        }
      const std::string cmd =
        "'" + tool + "' '" + dir + "' > '" + dir + "/report.log' 2>&1";
      if (std::system(cmd.c_str()) == 0)
        pcout << "report: " << dir << "/report/report.md" << std::endl;
      else
        {
          // The run itself succeeded: say why there is no report, go on.
          std::ifstream log(dir + "/report.log");
          std::string   line, last;
          while (std::getline(log, line))
            if (!line.empty())
              last = line;
          std::cerr << "formsolve: warning: no run report (" << last
                    << "); see " << dir << "/report.log" << std::endl;
        }
    }

    // The class is instantiated in time_loop.cc; these members are defined
    // here.
#define INSTANTIATE(dim)                                                       \
  template postprocess::FormingMeasures<dim> TimeLoop<dim>::measure_forming(); \
  template postprocess::SplitEvent<dim>      TimeLoop<dim>::check_fracture(    \
    const postprocess::FormingMeasures<dim> &,                            \
    RunSummary &);                                                        \
  template void        TimeLoop<dim>::measure_memory(RunSummary &) const;      \
  template void        TimeLoop<dim>::write_summary(const RunSummary &) const; \
  template std::string TimeLoop<dim>::split_summary() const;                   \
  template std::string TimeLoop<dim>::bead_summary() const;                    \
  template std::vector<std::string> TimeLoop<dim>::run_warnings() const;       \
  template void                     TimeLoop<dim>::make_report() const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
