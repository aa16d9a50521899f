// Output files that are never left truncated: each is written under a
// temporary name and renamed, so that a process killed at any moment leaves
// either the previous file or the complete new one.
#pragma once

#include <deal.II/base/data_out_base.h>

#include <mpi.h>

#include <functional>
#include <ostream>
#include <string>

namespace formsolve
{
  namespace postprocess
  {
    /// Writes @p path through @p write (into path.tmp, then renamed).
    void write_atomically(const std::string                         &path,
                          const std::function<void(std::ostream &)> &write);

    /// DataOut's write_vtu_with_pvtu_record, atomically (collective): every
    /// rank writes its piece <base>_<step>.<rank>.vtu, and rank 0 writes the
    /// .pvtu record once all pieces are complete. Returns the record's name
    /// (without the directory), for the .pvd list.
    template <int dim, int spacedim>
    std::string
    write_vtu_atomically(const dealii::DataOutInterface<dim, spacedim> &out,
                         const std::string &directory,
                         const std::string &base,
                         const unsigned int step,
                         const MPI_Comm     comm);

    /// The same with each rank's part in @p n_pieces pieces, one at a time
    /// in memory: @p make(k) turns @p out into piece k before it is written.
    /// The pieces are <base>_<step>.<rank n_pieces + k>.vtu.
    template <int dim, int spacedim>
    std::string
    write_vtu_atomically(const dealii::DataOutInterface<dim, spacedim> &out,
                         const unsigned int                       n_pieces,
                         const std::function<void(unsigned int)> &make,
                         const std::string                       &directory,
                         const std::string                       &base,
                         const unsigned int                       step,
                         const MPI_Comm                           comm);
  } // namespace postprocess
} // namespace formsolve
