// Orientation of a triangulated tool surface from CAD: neighbours made to
// agree, closed parts turned to face outwards. Files from CAD exporters
// often mix orientations; what was changed is reported, not hidden.
#pragma once

#include <formsolve/tools/surface_file.h>

#include <string>

namespace formsolve
{
  namespace tools
  {
    struct SurfaceOrientation
    {
      unsigned int parts      = 0; // connected parts
      unsigned int open_parts = 0; // parts with a boundary edge
      unsigned int turned     = 0; // triangles turned to agree with neighbours
      unsigned int turned_out = 0; // closed parts that were inside out
      unsigned int degenerate = 0; // triangles without area, left out
      unsigned int repeated   = 0; // triangles given twice, left out
      unsigned int joined     = 0; // vertices at one position, joined

      /// What was changed, one sentence naming @p file; empty if nothing.
      std::string describe(const std::string &file) const;
    };

    /// Drops triangles without area, joins vertices at one position and
    /// drops triangles given twice (CGAL's soup repair), and orients
    /// @p mesh: across every edge
    /// the two triangles agree (in each open part the file's majority
    /// orientation is kept), every closed part encloses a positive volume
    /// (normals outwards). An edge of three or more triangles, or a part
    /// that cannot be oriented (a Moebius strip), is an error naming @p file
    /// and the edge.
    SurfaceOrientation orient(SurfaceMesh &mesh, const std::string &file);
  } // namespace tools
} // namespace formsolve
