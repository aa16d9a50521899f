// Magnitudes that look like the wrong unit or an implausible process
// (lengths in metres, stresses in Pa, a holder force far from Siebel's rule,
// high friction), and Siebel's blank-holder force itself (doc/theory.md,
// section 6b; doc/user-guide.md, section 1.4 and "Blank holder").
#pragma once

#include <formsolve/parameters/parameters.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    /// The tensile strength R_m (MPa): Material/Tensile strength, or from
    /// the flow curve at Considere's uniform strain (engineering stress).
    double tensile_strength(const Material &m);

    struct SiebelEstimate
    {
      bool   applies  = false; // round blank, punch and holder opening
      double pressure = 0;     // MPa
      double force    = 0;     // N, full part
      double area     = 0;     // mm^2, initial flange under the holder
    };

    /// Siebel's rule p = c [(beta - 1)^2 + d_p/(200 t0)] R_m, c = 0.0025,
    /// beta = d0/d_p, on the initial flange under the holder.
    SiebelEstimate siebel(const Run &run);

    /// One sentence per suspicious value, naming the entry.
    std::vector<std::string> plausibility_warnings(const Run &run);
  } // namespace parameters
} // namespace formsolve
