// Subsection "Springback": the elastic release of the formed part after the
// last step (doc/springback.md; doc/theory.md, section 12).
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    /// A point that holds the part during the release, as a measuring
    /// fixture does: the mesh node nearest to it has the named displacement
    /// components fixed.
    struct SupportPoint
    {
      std::vector<double> coordinates; // the model's coordinates (mm)
      std::string         components;  // letters of coordinate_names()
    };

    struct Springback
    {
      bool         enabled = false;
      unsigned int degree  = 0; // of the release's displacement; 0: forming's
      /// Empty: the minimal support (statically determinate).
      std::vector<SupportPoint> supports;
      /// Where the springback normal to the part is reported (model's
      /// coordinates, end of forming, mm).
      std::vector<std::vector<double>> measure_points;
      /// The split-ring test: the half model's symmetry plane x = 0 opens
      /// where y > 0 (a slit along the generator at +y).
      bool         slit           = false;
      double       tolerance      = 1e-8; // |r| / |f_release|
      unsigned int max_iterations = 30;
      /// The end state is a sound start where the plastic strain exceeds
      /// this many yield strains sigma_y/E (doc/theory.md, section 12).
      double sound_strain_ratio = 10;
      /// Warn when more than this fraction of the volume is not.
      double unsound_volume_warning = 0.25;

      /// Declares the subsection, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };

    struct Run;
    /// What the release needs of the other subsections: Young's modulus,
    /// supports with the model's number of coordinates and its component
    /// names; throws naming the entry.
    void check_springback(const Run &run);

    /// "x, y, z; x, y, z" -> points; throws naming Springback/Measure
    /// points.
    std::vector<std::vector<double>> parse_points(const std::string &text);

    /// "x, y, z: xz; ..." -> support points; throws naming
    /// Springback/Supports.
    std::vector<SupportPoint> parse_supports(const std::string &text);
  } // namespace parameters
} // namespace formsolve
