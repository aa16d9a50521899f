// Subsection "Split": when the sheet counts as split, and what the run does
// then (doc/theory.md, section 11c).
#pragma once

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    /// What the run does once the sheet has split.
    enum class AfterSplit
    {
      stop,   // end the run Travel past the split after the first split
      proceed // go on, to see how the split grows
    };

    struct Split
    {
      /// Which measures mark a split (each is watched and reported anyway).
      bool       by_forming_limit = true; // a column past the FLC
      bool       by_neck          = true; // thinning localised, force falling
      bool       by_fracture      = true; // the fracture criterion reaching 1
      AfterSplit after            = AfterSplit::stop;
      double     travel_past      = 1.0; // mm of punch travel after the split
      /// A neck: the thinnest column thins this many times faster than its
      /// neighbours (2 to 5 t0 away) ...
      double neck_localisation = 4;
      /// ... at a thickness strain rate of at least this per mm of punch
      /// travel, while the punch force falls.
      double neck_thinning_rate = 0.05;

      /// Declares the subsection, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
