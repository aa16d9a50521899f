#include <deal.II/base/exceptions.h>

#include <formsolve/app/error_exit.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>

namespace formsolve
{
  namespace app
  {
    namespace
    {
      MPI_Comm error_comm = MPI_COMM_NULL;
    }

    void prepare_error_exit()
    {
      MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
    }

    std::string one_line(const std::string &text)
    {
      std::istringstream words(text);
      std::string        line, word;
      while (words >> word)
        line += (line.empty() ? "" : " ") + word;
      return line;
    }

    int error_exit(const std::string &message, const double wait_seconds)
    {
      int rank = 0, size = 1;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      MPI_Comm_size(MPI_COMM_WORLD, &size);
      bool everyone = size == 1;
      if (!everyone && error_comm != MPI_COMM_NULL)
        {
          MPI_Request request;
          MPI_Ibarrier(error_comm, &request);
          const auto end = std::chrono::steady_clock::now() +
                           std::chrono::duration<double>(wait_seconds);
          int done = 0;
          while (!done && std::chrono::steady_clock::now() < end)
            {
              MPI_Test(&request, &done, MPI_STATUS_IGNORE);
              if (!done)
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
          everyone = done != 0;
        }
      if (everyone)
        {
          if (rank == 0)
            std::cerr << "formsolve: error: " << message << std::endl;
          return 1;
        }
      // Only some ranks failed; the others wait in a collective for ever.
      std::cerr << "formsolve: error"
                << (rank != 0 ? " (rank " + std::to_string(rank) + ")" : "")
                << ": " << message << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }

    void injected_failure(const unsigned int step)
    {
      const char *r = std::getenv("FORMSOLVE_FAIL_ON_RANK");
      const char *s = std::getenv("FORMSOLVE_FAIL_AT_STEP");
      if (r == nullptr || s == nullptr)
        return;
      int rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      AssertThrow(rank != std::atoi(r) || step != unsigned(std::atoi(s)),
                  dealii::ExcMessage(
                    "injected failure (FORMSOLVE_FAIL_ON_RANK=" +
                    std::string(r) + ", FORMSOLVE_FAIL_AT_STEP=" + s + ")"));
    }

    void injected_kill(const std::string &point, const unsigned int step)
    {
      const char *k = std::getenv("FORMSOLVE_KILL_AT");
      if (k != nullptr && std::string(k) == point + ":" + std::to_string(step))
        std::raise(SIGKILL);
    }
  } // namespace app
} // namespace formsolve
