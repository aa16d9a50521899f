// The time loop's checks of its input before the first step: the scene (no
// blank inside a tool, holder and die acting on the blank) and the output
// directory, each failing with the parameter to change.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/contact/contact_search.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/time_loop.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
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
      AssertThrow(holder == state.tools.none ||
                    state.max_lateral_distance(holder) > 0,
                  ExcMessage(
                    "Tools/Blank holder/Diameter: no part of the blank "
                    "lies under the blank holder (its opening is as "
                    "large as the blank or larger); it would not act "
                    "on the flange"));
      AssertThrow(die == state.tools.none ||
                    state.max_lateral_distance(die) > 0,
                  ExcMessage("Tools/Die/Diameter: no part of the blank lies on "
                             "the die (its opening is as large as the blank or "
                             "larger)"));
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
      state.create_mesh();
      check_initial_scene();
      for (const auto &note : state.tools.notes())
        pcout << "note: " << note << "\n";
      pcout << "input valid: " << model::name(prm.geometry.model) << " model, "
            << state.tria.n_global_active_cells() << " cells, "
            << state.dof_handler.n_dofs() << " DoFs, " << state.tools.size()
            << " tool(s)" << std::endl;
    }

#define INSTANTIATE(dim)                                   \
  template void TimeLoop<dim>::check_initial_scene();      \
  template void TimeLoop<dim>::prepare_output_directory(); \
  template void TimeLoop<dim>::validate_scene();
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
