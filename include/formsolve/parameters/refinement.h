// Subsection "Mesh refinement": adaptive refinement near tool radii and by an
// error indicator (p4est; levels count from the initial mesh).
#pragma once

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class Indicator
    {
      none,
      kelly
    };

    struct MeshRefinement
    {
      unsigned int interval        = 0;    // steps between adaptations, 0: off
      unsigned int punch_level     = 0;    // max level near the punch radius
      unsigned int die_level       = 0;    // ... die profile radius
      unsigned int holder_level    = 0;    // ... blank-holder profile radius
      double       band_width      = 3;    // mm from the radius arc
      double       coarsen_factor  = 1.5;  // coarsen beyond this * band width
      double       shape_tolerance = 1e-3; // mm a coarsening may move a node
      Indicator    indicator       = Indicator::none;
      unsigned int indicator_level = 1; // max level the indicator refines to
      double       refine_fraction = 0.1, coarsen_fraction = 0.3;
      unsigned int min_layers = 4; // element layers at the radii

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      /// Needs Mesh/Layers through thickness.
      void validate(const unsigned int layers) const;
      bool enabled() const { return interval > 0; }
    };
  } // namespace parameters
} // namespace formsolve
