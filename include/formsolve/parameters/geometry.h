// Subsections "Geometry" (the model and the blank) and "Mesh".
#pragma once

#include <formsolve/model/model.h>

#include <string>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class BlankShape
    {
      round,     // a disk (its section in axisymmetry)
      rectangle, // length x width
      gmsh       // planform of the modelled part read from Mesh file
    };

    /// Subsection "Geometry": which model, and the blank (sheet) before
    /// forming.
    struct Geometry
    {
      model::Model model          = model::Model::axisymmetric;
      BlankShape   blank_shape    = BlankShape::round;
      double       blank_diameter = 77;   // mm
      double       blank_length   = 40;   // mm, full length along x
      double       blank_width    = 40;   // mm, full width along y
      double       thickness      = 0.78; // mm
      std::string  mesh_file;             // gmsh .msh or .geo (2-D planform)
      /// An earlier run's Output directory whose finished part this run
      /// forms further (a next operation); empty: a new blank.
      std::string start_from;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;

      /// Factor from the modelled part to the full part (4 for a quarter).
      double symmetry_factor() const { return model::symmetry_factor(model); }

      /// The width along y a plane-strain section stands for (mm; the blank
      /// width), 1 for the other models.
      double section_depth() const
      {
        return model == model::Model::plane_strain ? blank_width : 1.;
      }
    };

    /// Subsection "Mesh".
    struct Mesh
    {
      unsigned int degree      = 1;
      unsigned int layers      = 4;
      unsigned int refinements = 4;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
