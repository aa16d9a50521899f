#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/tool.h>

#include <cctype>
#include <cmath>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<ToolShape> shape_names{{"round", ToolShape::round},
                                          {"rounded rectangle",
                                           ToolShape::rounded_rectangle},
                                          {"flat", ToolShape::flat},
                                          {"mesh", ToolShape::mesh}};
      const Choice<GapFrom>   gap_from_names{{"blank", GapFrom::blank},
                                           {"part", GapFrom::part}};
    } // namespace

    std::string tool_key(const std::string &name)
    {
      std::string key = name;
      for (auto &ch : key)
        ch = ch == ' ' ? '_' : std::tolower(static_cast<unsigned char>(ch));
      return key;
    }

    void Tool::declare(Declarations &d)
    {
      d.add("Enabled", enabled, "Whether this tool takes part.");
      d.add(
        "Shape",
        shape,
        shape_names,
        "round: surface of revolution about the z axis (in the axisymmetric "
        "model its r-z profile); rounded rectangle: for square cups (3-D "
        "models); flat: an infinite plane; mesh: the triangulated surface "
        "of 'Mesh file' (3-D models) or its r-z profile (axisymmetric "
        "model), moved by 'Mesh offset' and by 'Gap' away from the sheet.");
      d.add("Diameter",
            diameter,
            number("mm", 0),
            "Round tools: punch diameter, die opening diameter, or blank "
            "holder inner diameter (mm).");
      d.add("Length",
            length,
            number("mm", 0),
            "Rounded rectangle: full size along x (mm).");
      d.add("Width",
            width,
            number("mm", 0),
            "Rounded rectangle: full size along y (mm).");
      d.add("Corner radius",
            corner_radius,
            number("mm", 0),
            "Rounded rectangle: in-plane corner radius (mm); at least the "
            "profile radius for a punch.");
      d.add("Profile radius",
            profile_radius,
            number("mm", 0),
            "Radius of the rounded working edge (punch nose, die "
            "entry) (mm).");
      d.add("Gap",
            gap,
            number("mm"),
            "Initial distance between the tool face and the sheet surface "
            "it acts on (mm). The die is below the sheet (z <= 0), punch "
            "and blank holder above (z >= thickness).");
      d.add("Gap measured from",
            gap_from,
            gap_from_names,
            "blank: Gap is measured from the blank's planes (z = 0 for tools "
            "below the sheet, z = Thickness above). part: the tool, placed "
            "first as for blank, moves along z until the smallest distance "
            "between it and the nodes of the part's surface facing it is Gap "
            "(a next operation's tools against the formed part, "
            "Geometry/Start from; for a flat blank the same as blank).");
      d.add("Friction coefficient",
            friction_coefficient,
            number("-", 0, 1.5),
            "Coulomb friction coefficient mu (-); above 0.5 "
            "(more than dry sheet forming shows) a warning.");
      d.add("Penalty factor",
            penalty_factor,
            number("N/mm^3", 0),
            "Fixed contact penalty for this tool (N/mm^3, contact pressure "
            "per mm of penetration); 0 takes Contact/Penalty factor.");
      d.add("Allowed penetration",
            allowed_penetration,
            number("mm", 0),
            "Adaptive penalty: allowed penetration delta into this tool (mm); "
            "0 takes Contact/Allowed penetration.");
      declare_mesh(d);
    }

    void Tool::declare_mesh(Declarations &d)
    {
      d.add(
        "Mesh file",
        mesh_file,
        input_file(),
        "Shape = mesh: the tool's surface in mm (a relative path is taken "
        "from the .prm file that names it, from the working directory with "
        "--set): STL (ASCII or binary) or a gmsh mesh (.msh, its "
        "triangles), or geometry gmsh meshes at 'Facet size' (.geo, STEP "
        ".step/.stp, IGES .iges/.igs, .brep). A closed surface is the "
        "tool's solid; an open one is its working face, its side the one "
        "the blank lies on. Normals are made to agree, each change said "
        "in the log. The axisymmetric model takes the tool's r-z profile: a "
        "CSV of r, z points (.csv, in order along the profile) or gmsh lines "
        "(.msh, or a .geo meshed at 'Facet size') drawn in the x-z plane or "
        "in the x-y plane (y as z); a closed profile is the section of the "
        "solid, an open one its working face.");
      d.add("Mesh offset",
            mesh_offset,
            numbers("mm", 3, 3),
            "Shape = mesh: translation x, y, z added to the file's "
            "coordinates (mm).");
      d.add("Facet size",
            facet_size,
            number("mm", 0),
            "Shape = mesh from .geo, STEP, IGES or BREP: the "
            "largest triangle (or profile segment) edge gmsh "
            "makes (mm).");
      d.add(
        "Feature angle",
        feature_angle,
        number("degrees", 0, 180),
        "Shape = mesh: neighbouring triangles (profile segments) whose "
        "normals differ by more than this (degrees) meet at a sharp edge; "
        "elsewhere the surface "
        "is smoothed (normals interpolated from the vertices, doc/theory.md "
        "eq. 7b).");
    }


    void Tool::validate() const
    {
      if (!enabled)
        return;
      const std::string e = "Tools/" + name + "/";
      require(std::isfinite(gap), e + "Gap", "must be a finite number (mm)");
      require(gap_from == GapFrom::blank || gap >= 0,
              e + "Gap",
              "must not be negative with 'Gap measured from' = part (the "
              "tool would start inside the part)");
      if (shape == ToolShape::round && name == "Punch")
        {
          require_positive(diameter, e + "Diameter", "mm");
          require(profile_radius <= 0.5 * diameter,
                  e + "Profile radius",
                  "must not exceed half the Diameter");
        }
      if (shape == ToolShape::mesh)
        {
          require(!mesh_file.empty(),
                  e + "Mesh file",
                  "must name the tool's surface file when Shape = mesh");
          require_positive(facet_size, e + "Facet size", "mm");
        }
      if (shape == ToolShape::rounded_rectangle)
        {
          require(length > 0 && width > 0,
                  e + "Length",
                  "Length and Width must be positive (mm)");
          require(corner_radius <= 0.5 * std::min(length, width),
                  e + "Corner radius",
                  "must not exceed half of Length and Width");
          if (name == "Punch")
            require(corner_radius >= profile_radius,
                    e + "Corner radius",
                    "must be at least the Profile radius for a punch");
        }
    }

  } // namespace parameters
} // namespace formsolve
