// The r-z profile of an axisymmetric tool from a file (Shape = mesh in the
// axisymmetric model): a CSV of r, z points, or the lines of a gmsh mesh
// (.msh) or of the curves gmsh meshes from a .geo file.
#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    /// Points (r, z) and segments. Segments of a chain run head to tail.
    struct ProfileLines
    {
      std::vector<dealii::Point<2>>            points;
      std::vector<std::array<unsigned int, 2>> segments;

      /// For the broadcast from the rank that read it.
      template <class Archive>
      void serialize(Archive &archive, const unsigned int)
      {
        archive &points &segments;
      }
    };

    /// A CSV of r, z (mm), one point per line in the profile's order; lines
    /// starting with '#' and a header line without numbers are skipped.
    /// Errors name the file as @p what and the two numbers as @p names; r
    /// must be >= 0 if @p on_axis_side (a profile about the axis).
    ProfileLines read_profile_csv(const std::string &file,
                                  const std::string &what = "tool profile file",
                                  const std::string &names        = "r, z",
                                  const bool         on_axis_side = true);

    /// The line elements of a gmsh mesh, or of the curves of a .geo meshed
    /// with segments up to @p facet_size (mm), drawn in the x-z plane
    /// (y = 0: r = x, z = z) or in the x-y plane (z = 0: r = x, z = y).
    ProfileLines read_profile_with_gmsh(const std::string &file,
                                        const double       facet_size);

    /// By extension (.csv, .msh, .geo); errors name the file.
    ProfileLines read_profile(const std::string &file, const double facet_size);
  } // namespace tools
} // namespace formsolve
