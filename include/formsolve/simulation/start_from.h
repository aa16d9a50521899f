// A next operation (Geometry/Start from): the finished part of an earlier
// run, read from its end checkpoint, as this run's part at rest; the tools,
// time and contact start afresh (doc/next-operation.md).
#pragma once

#include <formsolve/simulation/checkpoint.h>

#include <string>

namespace formsolve
{
  namespace simulation
  {
    /// What the part brings from the earlier run.
    struct EarlierRun
    {
      std::string  folder;     // Geometry/Start from
      std::string  checkpoint; // its end checkpoint
      unsigned int steps  = 0;
      double       travel = 0;     // its punch travel at the end (mm)
      bool         sprung = false; // the shape after its springback
      std::string  end_reason;
      /// Where and when its part split (run-summary.txt), "" if it did not.
      std::string split;
    };

    /// Checks that Geometry/Start from names a finished, untrimmed run of
    /// this Geometry, Mesh and Material, and that @p output_directory is
    /// not that folder; throws one message naming the entry otherwise.
    /// @p listing: this run's complete parameter listing.
    EarlierRun find_earlier_run(const std::string &folder,
                                const std::string &output_directory,
                                const std::string &listing);

    /// The lines of run-summary.txt that name the earlier run (start_from,
    /// start_from_shape; empty values without one).
    std::string summary_lines(const EarlierRun *earlier);

    /// The earlier run's part into @p state (empty triangulation): mesh,
    /// history (strain, damage, stresses), and its shape at rest.
    template <int dim>
    void load_earlier_part(const EarlierRun &earlier, State<dim> &state);
  } // namespace simulation
} // namespace formsolve
