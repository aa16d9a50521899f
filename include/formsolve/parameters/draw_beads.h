// Subsection Tools/Draw beads: equivalent draw beads, each a line in plan
// view on the die/holder face (a point of the section in 2-D: the radius of
// a round bead in axisymmetry, its x in plane strain) with the forces per
// unit length it exerts, given directly or computed from the bead's
// geometry (beads/bead_model.h). Names are read ahead, as those of
// Tools/Additional tools, so that each bead's subsection can be declared.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class BeadModel
    {
      forces,  // restraining and opening force per length as given
      geometry // from height, radii and friction (doc/theory.md, 6d)
    };

    struct DrawBead
    {
      std::string name;
      /// Plan-view points (x, y) in mm; in 2-D one point (x, 0).
      std::vector<std::pair<double, double>> line;
      std::string                            line_text = ""; // no default place
      bool                                   closed    = false;
      BeadModel                              model     = BeadModel::forces;
      /// N/mm at the line's start [and end, linear along the line].
      std::vector<double> restraining = {0.};
      std::vector<double> opening     = {0.};
      double              height      = 3; // mm, of the bead (full penetration)
      double              bead_radius = 4; // mm (geometry)
      double              shoulder_radius = 4;   // mm (geometry)
      double              friction        = 0.1; // - (geometry)

      /// The entries of Tools/Draw beads/<name>, bound to these members.
      void declare(Declarations &d);
      /// @p section: a 2-D model (one point).
      void validate(const bool section) const;
      /// Line length in plan view (mm; 0 in 2-D).
      double length() const;
      /// "bead_<key>" of the history columns.
      std::string key() const;
    };

    struct DrawBeads
    {
      std::vector<DrawBead> beads;

      /// The entry Tools/Draw beads/Names (inside subsection Tools).
      void declare(Declarations &d);
      /// The subsections Tools/Draw beads/<name> of @p names (read ahead by
      /// draw_bead_names()).
      void declare_beads(Declarations                   &d,
                         const std::vector<std::string> &names);
      void validate(const bool section) const;
      bool any() const { return !beads.empty(); }
    };

    /// The names of Tools/Draw beads/Names in the input @p text (after the
    /// command line's @p overrides); empty if the text does not parse.
    std::vector<std::string> draw_bead_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides);
  } // namespace parameters
} // namespace formsolve
