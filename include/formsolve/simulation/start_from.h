// A next operation (Geometry/Start from): the finished part of an earlier
// run, read from its end checkpoint, as this run's part at rest; the tools,
// time and contact start afresh (doc/next-operation.md).
#pragma once

#include <formsolve/simulation/checkpoint.h>
#include <formsolve/state/history_update.h>
#include <formsolve/trimming/part_mesh.h>

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
      /// Trimmed: the part gets its own mesh (trimming/part_mesh.h).
      bool               trimmed = false;
      trimming::PartMesh part_mesh;
      /// The part's volume (mm^3, the model) and integral of the equivalent
      /// plastic strain at the start, and the earlier run's of it (its
      /// trimming_volume and trimming_strain_integral; if untrimmed the
      /// same).
      double      volume = 0, earlier_volume = 0;
      double      strain = 0, earlier_strain = 0;
      std::string end_reason;
      /// Where and when its part split (run-summary.txt), "" if it did not.
      std::string split;
      /// Why its Trimming failed (run-summary.txt), "" if it did not.
      std::string trim_failure;
    };

    /// Checks that Geometry/Start from names a finished run of
    /// this Geometry, Mesh and Material, and that @p output_directory is
    /// not that folder; throws one message naming the entry otherwise.
    /// @p listing: this run's complete parameter listing.
    EarlierRun find_earlier_run(const std::string &folder,
                                const std::string &output_directory,
                                const std::string &listing);

    /// The lines of run-summary.txt that name the earlier run (start_from,
    /// start_from_shape, start_from_trimmed, the part's volume and, if
    /// trimmed, its mesh; empty values without one).
    std::string summary_lines(const EarlierRun *earlier);

    /// The earlier run's part into @p state (empty triangulation): mesh,
    /// history (strain, damage, stresses), and its shape at rest. A trimmed
    /// part is moved onto a mesh of its own (@p update carries the volume
    /// offsets); fills @p earlier's part_mesh and volumes.
    template <int dim>
    void load_earlier_part(EarlierRun                      &earlier,
                           State<dim>                      &state,
                           const state::HistoryUpdate<dim> &update);
  } // namespace simulation
} // namespace formsolve
