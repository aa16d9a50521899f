// Work that one rank does for all: files read and meshed once (a tool's
// surface through gmsh takes seconds and memory), the result broadcast.
#pragma once

#include <deal.II/base/mpi.h>

#include <formsolve/app/error_exit.h>

#include <boost/serialization/array.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <string>
#include <utility>

namespace formsolve
{
  namespace app
  {
    /// @p read() on rank 0 of @p comm only, its result broadcast (T must be
    /// serializable by boost): every rank returns the same value, or throws
    /// the same error with rank 0's message, so that an error in a file is
    /// one error of all ranks (collective).
    template <typename T, typename F>
    T on_rank_zero(const MPI_Comm comm, F &&read)
    {
      std::pair<std::string, T> result; // an error's message, the value
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            result.second = read();
          }
        catch (const std::exception &e)
          {
            result.first = exception_text(e);
            if (result.first.empty())
              result.first = "an error without a message";
          }
      if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        result = dealii::Utilities::MPI::broadcast(comm, result, 0);
      AssertThrow(result.first.empty(), dealii::ExcMessage(result.first));
      return std::move(result.second);
    }
  } // namespace app
} // namespace formsolve
