// formsolve: parse the command line and the .prm file, validate, run.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <formsolve/parameters/command_line.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/simulation/simulation.h>

#include <iostream>
#include <sstream>

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
      formsolve::parameters::Run run;
      run.parse(prm);
      run.validate();
      formsolve::simulation::Simulation<3> simulation(run, prm);
      if (cl.validate)
        simulation.validate_scene();
      else
        simulation.run();
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
