// formsolve: parse the command line and the .prm file, validate, dispatch on
// the model (2-D axisymmetric or 3-D), run, and report errors.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <formsolve/app/error_exit.h>
#include <formsolve/parameters/command_line.h>
#include <formsolve/parameters/manual.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/parameters/plausibility.h>
#include <formsolve/simulation/time_loop.h>

#include <iostream>
#include <sstream>

namespace
{
  /// Errors are handled here, while the simulation objects still exist:
  /// some of their destructors are collective (MUMPS), and a rank whose
  /// error the others do not share must not wait in them.
  template <int dim>
  int run(const formsolve::parameters::Run         &run,
          const dealii::ParameterHandler           &prm,
          const formsolve::parameters::CommandLine &cl)
  {
    formsolve::simulation::TimeLoop<dim> loop(run, prm);
    int                                  rc = 0;
    try
      {
        if (cl.validate)
          loop.validate_scene();
        else
          loop.run(cl.resume);
      }
    catch (const std::exception &e)
      {
        // Returns only if every rank has the error; else the job ends here.
        rc = formsolve::app::error_exit(formsolve::app::exception_text(e));
      }
    loop.make_report();
    return rc;
  }
} // namespace

int main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  formsolve::app::prepare_error_exit();
  using formsolve::parameters::CommandLine;
  // A command line it cannot use: the error on one line, then the usage
  // with its lines (every rank parses the same arguments).
  const auto usage_error = [root](const std::string &what) {
    const int rc = formsolve::app::error_exit(what);
    if (root)
      std::cerr << CommandLine::usage();
    return rc;
  };
  CommandLine cl;
  try
    {
      cl = CommandLine::parse(argc, argv);
    }
  catch (const std::exception &e)
    {
      return usage_error(formsolve::app::exception_text(e));
    }
  if (!cl.help && !cl.print_parameters && !cl.parameter_manual &&
      cl.input_file.empty())
    return usage_error("no input file given");
  try
    {
      if (cl.help)
        {
          if (root)
            std::cout << CommandLine::usage();
          return 0;
        }
      ParameterHandler                    prm;
      formsolve::parameters::Run          parameters;
      formsolve::parameters::Declarations declarations(prm);
      parameters.declare(declarations);
      if (cl.print_parameters || cl.parameter_manual)
        {
          if (root && cl.print_parameters)
            formsolve::parameters::write_parameter_file(declarations.tree(),
                                                        std::cout);
          else if (root)
            {
              // One additional tool shows the entries each of them has.
              parameters.tools.declare_additional(declarations, {"<name>"});
              parameters.tools.draw_beads.declare_beads(declarations,
                                                        {"<name>"});
              formsolve::parameters::write_manual(declarations.tree(),
                                                  std::cout);
            }
          return 0;
        }
      formsolve::parameters::read_input(declarations, parameters.tools, cl);
      parameters.complete();
      parameters.validate();
      if (root)
        {
          if (parameters.tools.holder_force_by_siebel)
            {
              const auto s = formsolve::parameters::siebel(parameters);
              std::cout << "blank-holder force by Siebel's rule: " << s.force
                        << " N (p = " << s.pressure << " MPa on " << s.area
                        << " mm^2, R_m = "
                        << formsolve::parameters::tensile_strength(
                             parameters.material)
                        << " MPa)\n";
            }
          for (const auto &w :
               formsolve::parameters::plausibility_warnings(parameters))
            std::cout << "warning: " << w << "\n";
        }
      return formsolve::model::space_dimension(parameters.geometry.model) == 2
               ? run<2>(parameters, prm, cl)
               : run<3>(parameters, prm, cl);
    }
  catch (const std::exception &e)
    {
      return formsolve::app::error_exit(formsolve::app::exception_text(e));
    }
}
