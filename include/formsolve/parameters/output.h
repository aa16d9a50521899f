// Subsection "Output".
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    struct Output
    {
      std::string         directory = "results/cup-drawing";
      unsigned int        interval  = 5; // VTU every N steps (0: never)
      bool                wall_time_in_history = true;
      bool                revolved_copy = false; // axisymmetric: 3-D VTU too
      bool                revolved_every_output = false; // else the last only
      double              revolved_angle        = 270;   // degrees swept
      bool                report                = true;  // report/ at the end
      unsigned int        checkpoint_interval   = 0;     // steps; 0: off
      double              checkpoint_minutes    = 10;    // wall time; 0: off
      std::vector<double> profile_travels; // mm: sheet_<travel>mm.csv there

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
