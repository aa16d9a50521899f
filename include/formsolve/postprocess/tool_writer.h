// The tools as surfaces beside the sheet: tools_<step>.vtu and tools.pvd at
// every output step, so that ParaView shows the process.
#pragma once

#include <formsolve/parameters/draw_beads.h>
#include <formsolve/tools/tool_set.h>
#include <formsolve/tools/tool_surface.h>

#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    template <int dim>
    class ToolWriter
    {
    public:
      explicit ToolWriter(const std::string &directory);

      /// Rank 0 writes tools_<step>.vtu (cells with a field `tool`, the
      /// tool's index in history.csv's order) and rewrites tools.pvd.
      /// Each tool is drawn over @p extent where it is unbounded; each draw
      /// bead of @p beads as a band across the sheet's initial thickness
      /// @p t0 along its line (a line in 2-D), `tool` = number of tools +
      /// the bead's index.
      void write(const unsigned int           step,
                 const double                 time,
                 const tools::ToolSet<dim>   &tools,
                 const tools::SurfaceExtent  &extent,
                 const parameters::DrawBeads &beads,
                 const double                 t0,
                 const MPI_Comm               comm);

      /// The (time, file) records of tools.pvd, for checkpoints.
      using Records = std::vector<std::pair<double, std::string>>;
      const Records &pvd_records() const { return records; }
      void           set_records(const Records &r) { records = r; }

    private:
      std::string directory;
      Records     records;
    };
  } // namespace postprocess
} // namespace formsolve
