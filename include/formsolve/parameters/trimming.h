// Subsection "Trimming": where the formed part is cut after the last step
// (doc/trimming.md): half-spaces, a curve in plan view projected along z,
// a surface; the part kept is where every given cut keeps it.
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    /// "a x + b y + c z < d" (or >): the half-space kept. Coefficients by
    /// the coordinate's letter (r, x, y, z).
    struct PlaneCut
    {
      std::vector<std::pair<char, double>> terms;
      bool                                 keep_greater = false;
      double                               value        = 0; // mm
      std::string                          text;             // as given
    };

    enum class CurveSide
    {
      inside,  // a closed curve
      outside, // a closed curve
      left,    // an open curve, walking along it from its first point
      right
    };

    enum class SurfaceSide
    {
      behind,  // against the surface's normals
      in_front // where its normals point
    };

    struct Trimming
    {
      std::vector<PlaneCut> planes;
      std::string           curve_file; // x, y per line (mm), plan view
      CurveSide             curve_side = CurveSide::inside;
      std::string           surface_file; // STL or gmsh
      SurfaceSide           surface_side = SurfaceSide::behind;
      double                tolerance    = 0.5; // mm, of the cut edge
      unsigned int          max_passes   = 4;   // refinement passes

      bool any() const
      {
        return !planes.empty() || !curve_file.empty() || !surface_file.empty();
      }

      void declare(Declarations &d);
      void validate() const;
    };

    struct Run;
    /// The cuts against the model: coordinate letters, a plan-view curve or
    /// a surface only in 3-D; throws naming the entry.
    void check_trimming(const Run &run);

    /// "inside", "outside", "left", "right".
    std::string name(const CurveSide side);

    /// "z > 8; x + 0.5 z < 30" -> cuts; throws naming Trimming/Planes.
    std::vector<PlaneCut> parse_plane_cuts(const std::string &text);
  } // namespace parameters
} // namespace formsolve
