// The time loop's checks of its input before the first step: the scene (no
// blank inside a tool, holder and die acting on the blank) and the output
// directory, each failing with the parameter to change.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/beads/bead_operator.h>
#include <formsolve/contact/contact_search.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/time_loop.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    template <int dim>
    void TimeLoop<dim>::check_initial_scene()
    {
      contact::ContactSearch<dim>(prm.contact.search_distance)
        .evaluate(state.tools,
                  state.tools.velocities(),
                  state.displacement_ghost,
                  state.velocity_ghost,
                  0.,
                  state.contact_state,
                  state.contact_set);
      for (unsigned int t = 0; t < state.tools.size(); ++t)
        {
          // Within the allowed penetration the contact is as accurate as it
          // will ever be: a meshed tool's smooth surface may bulge by that
          // much where its face meets a radius.
          const double tol   = std::max(1e-6 * prm.geometry.thickness,
                                      state.tools.allowed_penetration(t));
          double       worst = 0;
          for (const auto &p : state.contact_set.pairs)
            if (p.tool == t)
              worst = std::max(worst, -p.gap);
          worst = Utilities::MPI::max(worst, comm);
          std::ostringstream s;
          s << "Tools/" << state.tools[t].name()
            << ": the blank starts inside this tool (" << worst
            << " mm deep); check its Gap, Diameter and Profile radius (or "
            << "Mesh offset) against Geometry";
          AssertThrow(worst <= tol, ExcMessage(s.str()));
        }
      // The holder must act on the flange, and the blank must lie on the die.
      const unsigned int holder = state.tools.holder_index(),
                         die    = state.tools.die_index();
      AssertThrow(die == state.tools.none ||
                    state.max_lateral_distance(die) > 0,
                  ExcMessage(die_message()));
      AssertThrow(holder == state.tools.none ||
                    state.max_lateral_distance(holder) > 0,
                  ExcMessage(
                    "Tools/Blank holder/Diameter: no part of the blank "
                    "lies under the blank holder (its opening is as "
                    "large as the blank or larger); it would not act "
                    "on the flange"));
      if (prm.tools.draw_beads.any())
        {
          beads::BeadOperator<dim> beads(prm, material, state.kinematics);
          beads.check_scene(state);
          for (const auto &line : beads.describe())
            pcout << "note: " << line << "\n";
        }
      if (prm.springback.enabled)
        springback::check_supports(state); // before any work
      if (prm.trimming.any())
        trimming::check_trim_curve(state, prm.trimming);
      scene_warnings.clear();
      state.update_contact_areas(); // which surface faces which tool
      check_reach();
      check_resolution();
      for (const auto &w : scene_warnings)
        pcout << "warning: " << w << "\n";
    }

    template <int dim>
    void TimeLoop<dim>::check_reach()
    {
      // The sheet moves at most as far as the punch; a tool comes nearer by
      // its own stroke (prescribed; at its speed over the run without one)
      // and without bound under force control.
      const auto  &tools  = state.tools;
      const double stroke = tools.punch_stroke();
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          const auto  &m = tools.motion(t);
          const double own =
            t == tools.punch_index() ? 0.
            : m.kind == parameters::ToolMotion::prescribed
              ? (m.stroke > 0 ? m.stroke
                              : m.speed * stroke / tools.punch_speed())
            : m.kind == parameters::ToolMotion::force
              ? std::numeric_limits<double>::infinity()
              : 0.;
          const double       reach = stroke + own;
          const double       d     = state.min_distance(t);
          std::ostringstream s;
          s.precision(4);
          if (d == std::numeric_limits<double>::max())
            s << "Tools/" << tools[t].name()
              << ": no part of the sheet's surface faces this tool; it will "
                 "never touch the sheet (check its position and Shape)";
          else if (d > reach + tools.allowed_penetration(t))
            s << "Tools/" << tools[t].name() << ": the tool is " << d
              << " mm from the sheet, farther than the run brings them "
                 "together ("
              << reach << " mm: the punch's Stroke"
              << (own > 0 ? " and the tool's own" : "")
              << "); it will never touch the sheet (check its Gap, Mesh "
                 "offset and the Stroke)";
          if (!s.str().empty())
            scene_warnings.push_back(s.str());
        }
    }

    template <int dim>
    void TimeLoop<dim>::check_resolution()
    {
      // Smallest in-plane cell size, and as refined at the radii.
      double h = std::numeric_limits<double>::max();
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (unsigned int d = 0; d + 1 < dim; ++d)
            h = std::min(h, cell->extent_in_direction(d));
      h                    = Utilities::MPI::min(h, comm);
      const auto        &r = prm.refinement;
      const unsigned int levels =
        r.enabled() ? std::max({r.punch_level, r.die_level, r.holder_level})
                    : 0;
      h                         = std::ldexp(h, -int(levels));
      const double       travel = prm.time.time_step * prm.tools.punch_speed;
      std::ostringstream s;
      s.precision(3);
      if (travel > h)
        {
          s << "Time stepping/Time step = " << prm.time.time_step
            << " s moves the punch " << travel
            << " mm per step, more than the smallest elements (" << h
            << " mm in the plane" << (levels > 0 ? " at the tool radii" : "")
            << "): the sheet wraps a radius over fewer steps than it has "
               "elements there; a step of at most "
            << h / prm.tools.punch_speed << " s resolves them";
          scene_warnings.push_back(s.str());
        }
      // Bending over a radius needs layers through the thickness.
      const bool bends = [&] {
        for (const auto *t : {&prm.tools.punch, &prm.tools.die})
          if (t->enabled && t->shape != parameters::ToolShape::flat)
            return true;
        return false;
      }();
      const unsigned int needed = prm.mesh.degree == 1 ? 4 : 2;
      const unsigned int layers = prm.mesh.layers << levels;
      if (bends && layers < needed)
        {
          std::ostringstream l;
          l << "Mesh/Layers through thickness = " << prm.mesh.layers
            << (levels > 0
                  ? " (" + std::to_string(layers) + " at the refined radii)"
                  : std::string())
            << ": bending over the tool radii needs at least " << needed
            << " layers of Q" << prm.mesh.degree
            << " elements; fewer overestimate the bending stiffness and "
               "miss the thinning there";
          scene_warnings.push_back(l.str());
        }
    }

    template <int dim>
    void TimeLoop<dim>::prepare_output_directory()
    {
      const std::string &dir = prm.output.directory;
      int                ok  = 1;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::error_code ec;
          std::filesystem::create_directories(dir, ec);
          const std::string probe = dir + "/.formsolve-write-test";
          ok                      = !ec && std::ofstream(probe).good();
          std::filesystem::remove(probe, ec);
          if (ok)
            parameter_handler.print_parameters(dir + "/parameters.prm",
                                               ParameterHandler::PRM);
        }
      ok = Utilities::MPI::min(ok, comm);
      AssertThrow(ok,
                  ExcMessage(
                    "Output/Output directory: cannot create or write '" + dir +
                    "'"));
    }

    template <int dim>
    void TimeLoop<dim>::validate_scene()
    {
      make_part();
      check_initial_scene();
      for (const auto &note : state.tools.notes())
        pcout << "note: " << note << "\n";
      pcout << "input valid: " << model::name(prm.geometry.model) << " model, "
            << state.tria.n_global_active_cells() << " cells, "
            << state.dof_handler.n_dofs() << " DoFs, " << state.tools.size()
            << " tool(s)" << std::endl;
    }

    template <int dim>
    std::string TimeLoop<dim>::die_message() const
    {
      std::ostringstream s;
      const auto        &g = prm.geometry;
      const auto        &d = prm.tools.die;
      if (g.blank_shape == parameters::BlankShape::round &&
          d.shape == parameters::ToolShape::round)
        s << "Geometry/Blank diameter = " << g.blank_diameter
          << " mm: the blank does not reach the die, whose opening "
             "(Tools/Die/Diameter) is "
          << d.diameter << " mm"
          << (g.blank_diameter < 1 ? "; lengths are in mm, not m" : "");
      else
        s << "Tools/Die: no part of the blank lies on the die (its opening "
             "is as large as the blank or larger; check Geometry and "
             "Tools/Die)";
      return s.str();
    }

#define INSTANTIATE(dim)                                          \
  template void        TimeLoop<dim>::check_initial_scene();      \
  template void        TimeLoop<dim>::check_reach();              \
  template void        TimeLoop<dim>::check_resolution();         \
  template std::string TimeLoop<dim>::die_message() const;        \
  template void        TimeLoop<dim>::prepare_output_directory(); \
  template void        TimeLoop<dim>::validate_scene();
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
