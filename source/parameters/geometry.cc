#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/geometry.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<BlankShape> blank_shape_names{{"round", BlankShape::round},
                                                 {"rectangle",
                                                  BlankShape::rectangle},
                                                 {"gmsh", BlankShape::gmsh}};
    } // namespace

    void Geometry::declare(Declarations &d)
    {
      const Subsection s(d, "Geometry");
      d.declare(
        "Model",
        model::name(model),
        one_of(model::model_names()),
        "Which part of the scene is modelled. axisymmetric: the r-z section "
        "of a round blank under round tools (2-D, the z axis is the axis of "
        "revolution; the cheapest faithful model of a cylindrical cup); "
        "plane strain: the x-z section x >= 0 of a long part (channel, rail, "
        "bend) with the symmetry plane x = 0 and no strain along y, for a "
        "rectangular blank whose Blank width is the part's length along y "
        "(2-D; round tools are straight along y with their profile in x-z); "
        "quarter: x >= 0, y >= 0 with symmetry planes x = 0 and y = 0; half: "
        "x >= 0 with the symmetry plane x = 0; full: the whole sheet; slice: "
        "the plane-strain section in 3-D, x >= 0 over 0 <= y <= Blank width "
        "with symmetry planes x = 0, y = 0 and y = Blank width (a thin "
        "rectangular blank under tools straight along y). Forces are always "
        "reported for the full part.",
        [this](const std::string &t) { model = model::parse_model(t); });
      d.add(
        "Blank shape",
        blank_shape,
        blank_shape_names,
        "Planform of the full blank: round (Blank diameter) or rectangle "
        "(Blank length x Blank width), of which the Model takes its part; "
        "gmsh reads the planform of the modelled part from 'Mesh file' (3-D "
        "models only). The sheet occupies 0 <= z <= Thickness.");
      d.add("Blank diameter",
            blank_diameter,
            number("mm", 0),
            "Diameter d0 of a round blank (mm).");
      d.add("Blank length",
            blank_length,
            number("mm", 0),
            "Full length of a rectangular blank along x (mm); plane strain: "
            "the section's length across the tools.");
      d.add("Blank width",
            blank_width,
            number("mm", 0),
            "Full width of a rectangular blank along y (mm); plane strain: "
            "the width the section stands for (forces are for it).");
      d.add("Thickness",
            thickness,
            number("mm"),
            "Initial sheet thickness t0 (mm).");
      d.add("Mesh file",
            mesh_file,
            input_file(),
            "For 'gmsh': a 2-D quadrilateral planform mesh (.msh) or a gmsh "
            "geometry (.geo, meshed on reading by gmsh into quadrilaterals) of "
            "the modelled part (quarter: x >= 0, y >= 0; half: x >= 0); it is "
            "extruded through the thickness. A relative path is taken from the "
            ".prm file that names it (from the working directory with --set).");
      d.add(
        "Start from",
        start_from,
        text("a folder path (relative to the working directory)"),
        "A next operation (redraw, restrike, flanging): the Output directory "
        "of an earlier finished run, whose part this run forms further with "
        "its own tools and stroke. The part keeps its mesh, shape (sprung if "
        "the earlier run released it: Springback/Enabled), thickness, "
        "equivalent strain, damage and stresses; a part the earlier run "
        "trimmed (Trimming) is meshed anew without the cells cut away and "
        "its shape and history carried over. Geometry, Mesh and Material "
        "must be those of the earlier run (Young's modulus, Poisson's ratio "
        "and Density aside). The tools are placed as for a new "
        "blank (Gap from the planes z = 0 and z = Thickness), or against "
        "the part with Tools/<tool>/Gap measured from = part. Nothing is "
        "written into that folder or below it. Empty: a new blank.");
    }


    void Geometry::validate() const
    {
      require_positive(thickness, "Geometry/Thickness", "mm");
      if (blank_shape == BlankShape::round)
        require_positive(blank_diameter, "Geometry/Blank diameter", "mm");
      if (blank_shape == BlankShape::rectangle)
        {
          require_positive(blank_length, "Geometry/Blank length", "mm");
          require_positive(blank_width, "Geometry/Blank width", "mm");
        }
      if (blank_shape == BlankShape::gmsh)
        require(!mesh_file.empty(),
                "Geometry/Mesh file",
                "must name a .msh or .geo file when 'Blank shape' is gmsh");
      if (model == model::Model::axisymmetric)
        require(blank_shape == BlankShape::round,
                "Geometry/Blank shape",
                "must be round for Model = axisymmetric");
      if (model == model::Model::plane_strain || model == model::Model::slice)
        require(blank_shape == BlankShape::rectangle,
                "Geometry/Blank shape",
                "must be rectangle for Model = " + model::name(model) +
                  " (Blank length across the tools, Blank width along them)");
    }

    void Mesh::declare(Declarations &d)
    {
      const Subsection s(d, "Mesh");
      d.add("Element degree",
            degree,
            whole_number(1, 2),
            "Polynomial degree of the FE_Q velocity elements (1 or 2).");
      d.add(
        "Layers through thickness",
        layers,
        whole_number(1, 64),
        "Element layers through the sheet thickness. Bending needs at least "
        "4 layers of degree 1 or 2 layers of degree 2. A power of 2 (2, 4, "
        "8) lets p4est make the last in-plane refinements, so each rank "
        "stores only its part of the mesh; with an odd number, every rank "
        "stores the whole refined planform x layers.");
      d.add(
        "Planform refinements",
        refinements,
        whole_number(0, 12),
        "In-plane resolution. 3-D: global refinements of the coarse planform "
        "before it is extruded (each halves the in-plane element size). "
        "Axisymmetric: the blank radius is divided into 2^(this + 1) equal "
        "elements (the element size of the quarter model's radius).");
    }


    void Mesh::validate() const {}
  } // namespace parameters
} // namespace formsolve
