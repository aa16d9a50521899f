// The r-z section of an axisymmetric run revolved about the z axis into a
// 3-D hexahedral mesh, for pictures of the whole part.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <string>

namespace formsolve
{
  namespace postprocess
  {
    /// DataOut of the section with its field names and vector ranges
    /// readable (deal.II keeps them protected).
    class SectionDataOut : public dealii::DataOut<2>
    {
    public:
      using dealii::DataOut<2>::get_dataset_names;
      using dealii::DataOut<2>::get_nonscalar_data_ranges;
    };

    /// Sweeps the patches of @p section (built with one subdivision and no
    /// curved cells, so that the vertices are the deformed ones) through
    /// @p angle degrees and writes <directory>/revolved_<step>.vtu/.pvtu;
    /// vector fields (r, z) become (x, y, z). Returns the .pvtu name.
    std::string write_revolved(const SectionDataOut &section,
                               const double          angle,
                               const std::string    &directory,
                               const unsigned int    step,
                               const MPI_Comm        comm);
  } // namespace postprocess
} // namespace formsolve
