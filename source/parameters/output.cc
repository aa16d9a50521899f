#include <deal.II/base/utilities.h>

#include <formsolve/parameters/output.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    void Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry(
        "Output directory",
        "results/cup-drawing",
        Anything(),
        "Folder for parameters.prm, history.csv, run-summary.txt and the "
        "VTU/PVTU/PVD files; created if missing.");
      prm.declare_entry(
        "Output interval",
        "5",
        Integer(0),
        "Write VTU every this many steps (and the last step); 0: never.");
      prm.declare_entry(
        "Wall time in history",
        "true",
        Bool(),
        "Write measured wall times into solver.csv (false gives "
        "reproducible files, e.g. for regression tests).");
      prm.declare_entry(
        "Revolved copy",
        "false",
        Bool(),
        "Axisymmetric model: with every VTU of the r-z section also write "
        "the section revolved about the z axis as a 3-D mesh "
        "(revolved_<step>.pvtu, revolved.pvd), for pictures of the part.");
      prm.declare_entry(
        "Report",
        "true",
        Bool(),
        "At the end of the run write report/ (pictures and report.md) with "
        "the formsolve-report next to the formsolve binary (the same as "
        "running formsolve-report <Output directory>); a missing Python "
        "module is reported and does not fail the run.");
      prm.declare_entry(
        "Checkpoint interval",
        "0",
        Integer(0),
        "Write a checkpoint every this many steps (steps) into "
        "<Output directory>/checkpoint, and always when the run ends or "
        "stops; 'formsolve case.prm --resume' continues from it. 0: by "
        "Checkpoint wall time only.");
      prm.declare_entry(
        "Checkpoint wall time",
        "10",
        Double(0),
        "Also write a checkpoint once this much wall time (minutes) has "
        "passed since the last one, so that a killed long run can always be "
        "resumed; 0: off.");
      prm.declare_entry(
        "Profile travels",
        "",
        List(Double(0)),
        "Punch travels (mm, comma-separated) at which the sheet's columns "
        "are also written as sheet_<travel>mm.csv (as sheet.csv at the end); "
        "a step ends on each of them.");
      prm.declare_entry("Revolved angle",
                        "270",
                        Double(1, 360),
                        "Angle the revolved copy sweeps (degrees): 270 leaves "
                        "a quarter open to show the section.");
      prm.leave_subsection();
    }

    void Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory            = prm.get("Output directory");
      interval             = prm.get_integer("Output interval");
      wall_time_in_history = prm.get_bool("Wall time in history");
      revolved_copy        = prm.get_bool("Revolved copy");
      revolved_angle       = prm.get_double("Revolved angle");
      report               = prm.get_bool("Report");
      checkpoint_interval  = prm.get_integer("Checkpoint interval");
      checkpoint_minutes   = prm.get_double("Checkpoint wall time");
      profile_travels.clear();
      for (const auto &t :
           dealii::Utilities::split_string_list(prm.get("Profile travels")))
        profile_travels.push_back(dealii::Utilities::string_to_double(t));
      prm.leave_subsection();
    }

    void Output::validate() const
    {
      require(!directory.empty(),
              "Output/Output directory",
              "must not be empty");
    }
  } // namespace parameters
} // namespace formsolve
