#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/output.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    void Output::declare(Declarations &d)
    {
      const Subsection s(d, "Output");
      d.add("Output directory",
            directory,
            text("a folder path (relative to the working directory)"),
            "Folder for parameters.prm, history.csv, run-summary.txt and the "
            "VTU/PVTU/PVD files; created if missing.");
      d.add("Output interval",
            interval,
            whole_number(0),
            "Write VTU every this many steps (and the last step); 0: never.");
      d.add("Wall time in history",
            wall_time_in_history,
            "Write measured wall times into solver.csv (false gives "
            "reproducible files, e.g. for regression tests).");
      d.add("Revolved copy",
            revolved_copy,
            "Axisymmetric model: also write the section revolved about the z "
            "axis as a 3-D mesh (revolved_<step>.pvtu, revolved.pvd), for "
            "pictures of the part: with the last VTU of the section, or with "
            "every one (Revolved every output).");
      d.add("Revolved every output",
            revolved_every_output,
            "With Revolved copy: write it with every VTU of the section "
            "(true), not only with the last (false). It has about 50 times "
            "the section's cells and multiplies the output time by about 10 "
            "(the default cup: 1.2 s of a 3.2 s run); ParaView's Rotational "
            "Extrusion filter revolves any step of the section.");
      d.add("Report",
            report,
            "At the end of the run write report/ (pictures and report.md) with "
            "the formsolve-report next to the formsolve binary (the same as "
            "running formsolve-report <Output directory>); a missing Python "
            "module is reported and does not fail the run.");
      d.add("Checkpoint interval",
            checkpoint_interval,
            whole_number(0),
            "Write a checkpoint every this many steps (steps) into "
            "<Output directory>/checkpoint, and always when the run ends or "
            "stops; 'formsolve case.prm --resume' continues from it. 0: by "
            "Checkpoint wall time only.");
      d.add(
        "Checkpoint wall time",
        checkpoint_minutes,
        number("minutes", 0),
        "Also write a checkpoint once this much wall time (minutes) has "
        "passed since the last one, so that a killed long run can always be "
        "resumed; 0: off.");
      d.add(
        "Profile travels",
        profile_travels,
        numbers("mm", 0, 0, 0),
        "Punch travels (mm, comma-separated) at which the sheet's columns "
        "are also written as sheet_<travel>mm.csv (as sheet.csv at the end); "
        "a step ends on each of them.");
      d.add("Revolved angle",
            revolved_angle,
            number("degrees", 1, 360),
            "Angle the revolved copy sweeps (degrees): 270 leaves "
            "a quarter open to show the section.");
    }


    void Output::validate() const
    {
      require(!directory.empty(),
              "Output/Output directory",
              "must not be empty");
    }
  } // namespace parameters
} // namespace formsolve
