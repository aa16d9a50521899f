// The entries every tool subsection has: shape, size, gap, friction,
// contact settings and the surface file of a meshed tool.
#pragma once

#include <array>
#include <string>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class ToolShape
    {
      round,             // surface of revolution about the z axis
      rounded_rectangle, // for square cups (3-D models only)
      flat,              // an infinite plane
      mesh               // a triangulated surface from a file (3-D models)
    };

    /// Where a tool's Gap is measured from.
    enum class GapFrom
    {
      blank, // the planes z = 0 (tools below) and z = thickness (above)
      part   // the part's surface facing the tool, along z
    };

    /// A tool's name as history columns and fields carry it: lower case,
    /// '_' for spaces (Blank holder: blank_holder).
    std::string tool_key(const std::string &name);

    /// The entries every tool subsection (Punch, Die, Blank holder) has.
    struct Tool
    {
      std::string name; // subsection name, also the history column prefix
      bool        enabled              = true;
      ToolShape   shape                = ToolShape::round;
      double      diameter             = 40; // mm (round)
      double      length               = 40; // mm (rounded rectangle, along x)
      double      width                = 40; // mm (rounded rectangle, along y)
      double      corner_radius        = 8;  // mm (rounded rectangle, in plane)
      double      profile_radius       = 8;  // mm (fillet of the working edge)
      double      gap                  = 0; // mm, initial distance to the sheet
      GapFrom     gap_from             = GapFrom::blank;
      double      friction_coefficient = 0.1;
      double      penalty_factor       = 0; // N/mm^3; 0: Contact/Penalty factor
      double      allowed_penetration  = 0; // mm; 0: Contact/Allowed penetr.
      std::string mesh_file            = "";   // Shape = mesh: STL, .msh, CAD
      std::array<double, 3> mesh_offset{};     // mm, added to the file's points
      double                facet_size    = 1; // mm, CAD files meshed by gmsh
      double                feature_angle = 30; // degrees, sharp edges

      /// Round or rounded rectangle: a planform with an edge (an opening
      /// for the die and holder), which the scene's rules can compare.
      bool has_outline() const
      {
        return shape == ToolShape::round ||
               shape == ToolShape::rounded_rectangle;
      }

      /// Declares the common entries inside the current subsection, bound
      /// to these members (their values now are the defaults).
      void declare(Declarations &d);
      void validate() const;

    private:
      /// The entries of a Shape = mesh tool.
      void declare_mesh(Declarations &d);
    };

  } // namespace parameters
} // namespace formsolve
