// formsolve: parse the command line and the .prm file, validate, dispatch on
// the model (2-D axisymmetric or 3-D), run, and report errors.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <formsolve/parameters/command_line.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/simulation/time_loop.h>

#include <iostream>
#include <sstream>

namespace
{
  template <int dim>
  void run(const formsolve::parameters::Run         &run,
           const dealii::ParameterHandler           &prm,
           const formsolve::parameters::CommandLine &cl)
  {
    formsolve::simulation::TimeLoop<dim> loop(run, prm);
    if (cl.validate)
      loop.validate_scene();
    else
      loop.run();
  }
} // namespace

int main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      const auto cl = formsolve::parameters::CommandLine::parse(argc, argv);
      if (cl.help)
        {
          if (root)
            std::cout << formsolve::parameters::CommandLine::usage();
          return 0;
        }
      ParameterHandler prm;
      formsolve::parameters::Run::declare(prm);
      if (cl.print_parameters)
        {
          if (root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      AssertThrow(!cl.input_file.empty(),
                  ExcMessage("no input file given\n" +
                             formsolve::parameters::CommandLine::usage()));
      formsolve::parameters::read_input(prm, cl);
      formsolve::parameters::Run parameters;
      parameters.parse(prm);
      parameters.validate();
      if (formsolve::model::space_dimension(parameters.geometry.model) == 2)
        run<2>(parameters, prm, cl);
      else
        run<3>(parameters, prm, cl);
    }
  catch (const ExceptionBase &e)
    {
      if (root)
        {
          std::ostringstream s;
          e.print_info(s);
          // One line: deal.II's messages are indented and spread over lines.
          std::istringstream words(s.str());
          std::string        msg, word;
          while (words >> word)
            msg += (msg.empty() ? "" : " ") + word;
          std::cerr << "formsolve: error: " << msg << std::endl;
        }
      return 1;
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "formsolve: error: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
