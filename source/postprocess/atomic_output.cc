#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <formsolve/postprocess/atomic_output.h>

#include <filesystem>
#include <fstream>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    void write_atomically(const std::string                         &path,
                          const std::function<void(std::ostream &)> &write)
    {
      const std::string tmp = path + ".tmp";
      {
        std::ofstream f(tmp);
        AssertThrow(f.good(), ExcMessage("cannot write " + tmp));
        write(f);
        f.flush();
        AssertThrow(f.good(), ExcMessage("writing " + tmp + " failed"));
      }
      std::error_code ec;
      std::filesystem::rename(tmp, path, ec);
      AssertThrow(!ec,
                  ExcMessage("cannot rename " + tmp + " to " + path + ": " +
                             ec.message()));
    }

    template <int dim, int spacedim>
    std::string write_vtu_atomically(const DataOutInterface<dim, spacedim> &out,
                                     const std::string &directory,
                                     const std::string &base,
                                     const unsigned int step,
                                     const MPI_Comm     comm)
    {
      return write_vtu_atomically(
        out,
        1,
        [](unsigned int) {},
        directory,
        base,
        step,
        comm);
    }

    template <int dim, int spacedim>
    std::string
    write_vtu_atomically(const DataOutInterface<dim, spacedim>   &out,
                         const unsigned int                       n_pieces,
                         const std::function<void(unsigned int)> &make,
                         const std::string                       &directory,
                         const std::string                       &base,
                         const unsigned int                       step,
                         const MPI_Comm                           comm)
    {
      const unsigned int rank  = Utilities::MPI::this_mpi_process(comm),
                         ranks = Utilities::MPI::n_mpi_processes(comm);
      const std::string  stem  = base + "_" + Utilities::int_to_string(step, 5);
      const unsigned int digits =
        Utilities::needed_digits(std::max(ranks * n_pieces, 2u) - 1);
      auto piece = [&](const unsigned int p) {
        return stem + "." + Utilities::int_to_string(p, digits) + ".vtu";
      };
      // A failed write on one rank must not leave the others waiting: the
      // outcome is agreed on before the record is written.
      int ok = 1;
      try
        {
          for (unsigned int k = 0; k < n_pieces; ++k)
            {
              make(k);
              write_atomically(directory + "/" + piece(rank * n_pieces + k),
                               [&](std::ostream &f) { out.write_vtu(f); });
            }
        }
      catch (...)
        {
          ok = 0;
        }
      AssertThrow(Utilities::MPI::min(ok, comm) == 1,
                  ExcMessage("cannot write " + directory + "/" + stem +
                             ".*.vtu (Output/Output directory)"));
      const std::string record = stem + ".pvtu";
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          for (unsigned int p = 0; p < ranks * n_pieces; ++p)
            pieces.push_back(piece(p));
          write_atomically(directory + "/" + record, [&](std::ostream &f) {
            out.write_pvtu_record(f, pieces);
          });
        }
      return record;
    }

    template std::string write_vtu_atomically(const DataOutInterface<2, 2> &,
                                              const std::string &,
                                              const std::string &,
                                              unsigned int,
                                              MPI_Comm);
    template std::string write_vtu_atomically(const DataOutInterface<3, 3> &,
                                              const std::string &,
                                              const std::string &,
                                              unsigned int,
                                              MPI_Comm);
    template std::string
    write_vtu_atomically(const DataOutInterface<3, 3> &,
                         unsigned int,
                         const std::function<void(unsigned int)> &,
                         const std::string &,
                         const std::string &,
                         unsigned int,
                         MPI_Comm);
  } // namespace postprocess
} // namespace formsolve
