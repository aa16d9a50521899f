#include <deal.II/base/exceptions.h>

#include <formsolve/parameters/parameters.h>

#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    using dealii::ExcMessage;
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;

    namespace
    {
      // User errors name the entry as "Subsection/Entry".
      void require(const bool         condition,
                   const std::string &entry,
                   const std::string &what)
      {
        AssertThrow(condition, ExcMessage("Parameter " + entry + ": " + what));
      }

      std::string str(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace

    // ---------------------------------------------------------------- Geometry
    void Geometry::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry(
        "Blank shape",
        "quarter disk",
        Selection("disk|quarter disk|rectangle|quarter rectangle|gmsh"),
        "Planform of the blank. Quarter shapes are modelled with the "
        "symmetry planes x = 0 and y = 0; 'gmsh' reads the planform "
        "from 'Mesh file'. The sheet occupies 0 <= z <= Thickness.");
      prm.declare_entry("Blank diameter",
                        "77",
                        Double(0),
                        "Blank diameter for disk shapes (mm).");
      prm.declare_entry(
        "Blank length",
        "40",
        Double(0),
        "Full blank length along x for rectangles (mm); the quarter "
        "model covers 0 <= x <= length/2.");
      prm.declare_entry("Blank width",
                        "40",
                        Double(0),
                        "Full blank width along y for rectangles (mm).");
      prm.declare_entry("Thickness",
                        "0.78",
                        Double(),
                        "Initial sheet thickness t0 (mm).");
      prm.declare_entry(
        "Mesh file",
        "",
        Anything(),
        "For 'gmsh': a 2-D quadrilateral planform mesh (.msh) or a gmsh "
        "geometry (.geo, meshed on reading by gmsh into quadrilaterals); it is "
        "extruded through the thickness. Relative paths are taken from "
        "the working directory.");
      prm.declare_entry(
        "Symmetry planes",
        "xy",
        Selection("none|x|y|xy"),
        "Symmetry planes of a 'gmsh' blank: x means the plane x = 0 "
        "(no normal velocity), y the plane y = 0, xy both. Generated "
        "quarter shapes always use xy, full shapes none.");
      prm.leave_subsection();
    }

    void Geometry::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      blank_shape     = prm.get("Blank shape");
      blank_diameter  = prm.get_double("Blank diameter");
      blank_length    = prm.get_double("Blank length");
      blank_width     = prm.get_double("Blank width");
      thickness       = prm.get_double("Thickness");
      mesh_file       = prm.get("Mesh file");
      symmetry_planes = prm.get("Symmetry planes");
      prm.leave_subsection();
      if (blank_shape == "quarter disk" || blank_shape == "quarter rectangle")
        symmetry_planes = "xy";
      else if (blank_shape != "gmsh")
        symmetry_planes = "none";
    }

    void Geometry::validate() const
    {
      require(thickness > 0,
              "Geometry/Thickness",
              "must be positive (mm), got " + str(thickness));
      if (blank_shape == "disk" || blank_shape == "quarter disk")
        require(blank_diameter > 0,
                "Geometry/Blank diameter",
                "must be positive (mm), got " + str(blank_diameter));
      if (blank_shape == "rectangle" || blank_shape == "quarter rectangle")
        {
          require(blank_length > 0,
                  "Geometry/Blank length",
                  "must be positive (mm), got " + str(blank_length));
          require(blank_width > 0,
                  "Geometry/Blank width",
                  "must be positive (mm), got " + str(blank_width));
        }
      if (blank_shape == "gmsh")
        require(!mesh_file.empty(),
                "Geometry/Mesh file",
                "must name a .msh or .geo file when 'Blank shape' is gmsh");
    }

    double Geometry::symmetry_factor() const
    {
      return (symmetric_in_x() ? 2. : 1.) * (symmetric_in_y() ? 2. : 1.);
    }

    bool Geometry::symmetric_in_x() const
    {
      return symmetry_planes == "x" || symmetry_planes == "xy";
    }

    bool Geometry::symmetric_in_y() const
    {
      return symmetry_planes == "y" || symmetry_planes == "xy";
    }

    // -------------------------------------------------------------------- Mesh
    void Mesh::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      prm.declare_entry(
        "Element degree",
        "1",
        Integer(1, 2),
        "Polynomial degree of the FE_Q velocity elements (1 or 2).");
      prm.declare_entry(
        "Layers through thickness",
        "4",
        Integer(1, 64),
        "Number of hexahedral element layers through the sheet "
        "thickness. Bending needs at least 4 layers of degree 1 or 2 "
        "layers of degree 2.");
      prm.declare_entry(
        "Planform refinements",
        "4",
        Integer(0, 12),
        "Global refinements of the coarse 2-D planform before it is "
        "extruded (each halves the in-plane element size).");
      prm.leave_subsection();
    }

    void Mesh::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh");
      degree      = prm.get_integer("Element degree");
      layers      = prm.get_integer("Layers through thickness");
      refinements = prm.get_integer("Planform refinements");
      prm.leave_subsection();
    }

    void Mesh::validate() const {}

    // --------------------------------------------------------- Mesh refinement
    void MeshRefinement::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh refinement");
      prm.declare_entry(
        "Interval",
        "0",
        Integer(0),
        "Adapt the mesh before step 1 and then every this many steps "
        "(steps); 0 switches adaptive refinement off. Level 0 is the initial "
        "mesh (Mesh/Planform refinements): refinement never coarsens below "
        "it, so choose a coarse initial mesh and refine near the radii.");
      prm.declare_entry(
        "Punch level",
        "0",
        Integer(0, 6),
        "Refinement level of blank cells within 'Band width' of the punch "
        "profile radius (levels above the initial mesh; 0: no refinement).");
      prm.declare_entry("Die level",
                        "0",
                        Integer(0, 6),
                        "As 'Punch level', for the die profile radius.");
      prm.declare_entry("Blank holder level",
                        "0",
                        Integer(0, 6),
                        "As 'Punch level', for the blank-holder radius.");
      prm.declare_entry(
        "Band width",
        "3",
        Double(0),
        "Cells whose centre, less half the size of the initial cell they "
        "came from, lies within this distance (mm) of a tool's "
        "profile-radius arc, in the current configuration, are refined to "
        "that tool's level; make it cover the material that reaches the "
        "radius within 'Interval' steps.");
      prm.declare_entry(
        "Coarsening factor",
        "1.5",
        Double(1),
        "Cells refined for a radius are coarsened once their centre is "
        "farther than this times 'Band width' from it (-): hysteresis, so "
        "cells do not flip between levels.");
      prm.declare_entry(
        "Indicator",
        "none",
        Selection("none|kelly"),
        "Solution-based criterion, combined with the radius bands: kelly "
        "refines the cells with the largest jumps of the velocity gradient "
        "(KellyErrorEstimator, current configuration) and coarsens those "
        "with the smallest.");
      prm.declare_entry("Indicator level",
                        "1",
                        Integer(0, 6),
                        "Highest level the indicator refines to.");
      prm.declare_entry("Refine fraction",
                        "0.1",
                        Double(0, 1),
                        "Indicator: fraction of the cells refined (-).");
      prm.declare_entry("Coarsen fraction",
                        "0.3",
                        Double(0, 1),
                        "Indicator: fraction of the cells coarsened (-).");
      prm.declare_entry(
        "Minimum layers at radii",
        "4",
        Integer(1, 256),
        "Element layers through the thickness needed where the sheet bends "
        "(the bending test: 4 layers of Q1 give the limit moment within 2 "
        "%); every non-zero tool level must reach it.");
      prm.leave_subsection();
    }

    void MeshRefinement::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh refinement");
      interval         = prm.get_integer("Interval");
      punch_level      = prm.get_integer("Punch level");
      die_level        = prm.get_integer("Die level");
      holder_level     = prm.get_integer("Blank holder level");
      band_width       = prm.get_double("Band width");
      coarsen_factor   = prm.get_double("Coarsening factor");
      indicator        = prm.get("Indicator");
      indicator_level  = prm.get_integer("Indicator level");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      min_layers       = prm.get_integer("Minimum layers at radii");
      prm.leave_subsection();
    }

    void MeshRefinement::validate(const unsigned int layers) const
    {
      if (!enabled())
        return;
      require(punch_level + die_level + holder_level > 0 || indicator != "none",
              "Mesh refinement/Interval",
              "is non-zero, but no tool level is set and Indicator is none");
      const std::pair<const char *, unsigned int> levels[] = {
        {"Punch level", punch_level},
        {"Die level", die_level},
        {"Blank holder level", holder_level}};
      for (const auto &[name, level] : levels)
        require(level == 0 || (layers << level) >= min_layers,
                std::string("Mesh refinement/") + name,
                "gives " + std::to_string(layers << level) +
                  " layers through the thickness at the radius, fewer than "
                  "'Minimum layers at radii' (" +
                  std::to_string(min_layers) + ")");
      require(refine_fraction + coarsen_fraction <= 1,
              "Mesh refinement/Refine fraction",
              "plus Coarsen fraction must not exceed 1");
    }

    // ---------------------------------------------------------------- Material
    void Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry(
        "Strength coefficient",
        "829",
        Double(),
        "K in the flow stress sigma = K (eps0 + eps)^n (rate/rate0)^m "
        "(MPa). Default: material B, type 430 stainless.");
      prm.declare_entry("Hardening exponent",
                        "0.2",
                        Double(0, 1),
                        "Strain-hardening exponent n (-).");
      prm.declare_entry(
        "Prestrain",
        "0.002",
        Double(),
        "eps0 (-): keeps the initial flow stress K eps0^n non-zero.");
      prm.declare_entry(
        "Rate sensitivity",
        "0",
        Double(0, 1),
        "Strain-rate sensitivity m (-); 0 gives a rigid-plastic law.");
      prm.declare_entry(
        "Reference strain rate",
        "1",
        Double(),
        "rate0 in the flow stress law (1/s); also the scale of the "
        "volumetric penalty.");
      prm.declare_entry(
        "Limiting strain rate",
        "1e-4",
        Double(),
        "Below this equivalent strain rate (1/s) the material is "
        "treated as linear viscous (rigid zones): the effective "
        "viscosity is frozen at its value at this rate.");
      prm.declare_entry("Volumetric penalty",
                        "1e4",
                        Double(),
                        "alpha (-): the mean stress is sigma_m = alpha K/rate0 "
                        "tr(strain rate), integrated with reduced quadrature.");
      prm.leave_subsection();
    }

    void Material::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      strength_coefficient  = prm.get_double("Strength coefficient");
      hardening_exponent    = prm.get_double("Hardening exponent");
      prestrain             = prm.get_double("Prestrain");
      rate_sensitivity      = prm.get_double("Rate sensitivity");
      reference_strain_rate = prm.get_double("Reference strain rate");
      limiting_strain_rate  = prm.get_double("Limiting strain rate");
      volumetric_penalty    = prm.get_double("Volumetric penalty");
      prm.leave_subsection();
    }

    void Material::validate() const
    {
      require(strength_coefficient > 0,
              "Material/Strength coefficient",
              "must be positive (MPa), got " + str(strength_coefficient));
      require(prestrain > 0 || hardening_exponent == 0,
              "Material/Prestrain",
              "must be positive when the hardening exponent is non-zero");
      require(reference_strain_rate > 0,
              "Material/Reference strain rate",
              "must be positive (1/s)");
      require(limiting_strain_rate > 0,
              "Material/Limiting strain rate",
              "must be positive (1/s)");
      require(volumetric_penalty > 0,
              "Material/Volumetric penalty",
              "must be positive");
    }

    // ------------------------------------------------------------------- Tools
    void Tool::declare(ParameterHandler &prm, const Tool &d)
    {
      prm.enter_subsection(d.name);
      prm.declare_entry("Enabled",
                        d.enabled ? "true" : "false",
                        Bool(),
                        "Whether this tool takes part.");
      prm.declare_entry(
        "Shape",
        d.shape,
        Selection("round|rounded rectangle|flat"),
        "round: surface of revolution about the z axis; rounded "
        "rectangle: for square cups; flat: an infinite plane.");
      prm.declare_entry(
        "Diameter",
        str(d.diameter),
        Double(0),
        "Round tools: punch diameter, die opening diameter, or blank "
        "holder inner diameter (mm).");
      prm.declare_entry("Length",
                        str(d.length),
                        Double(0),
                        "Rounded rectangle: full size along x (mm).");
      prm.declare_entry("Width",
                        str(d.width),
                        Double(0),
                        "Rounded rectangle: full size along y (mm).");
      prm.declare_entry(
        "Corner radius",
        str(d.corner_radius),
        Double(0),
        "Rounded rectangle: in-plane corner radius (mm); at least the "
        "profile radius for a punch.");
      prm.declare_entry("Profile radius",
                        str(d.profile_radius),
                        Double(0),
                        "Radius of the rounded working edge (punch nose, die "
                        "entry) (mm).");
      prm.declare_entry(
        "Gap",
        str(d.gap),
        Double(),
        "Initial distance between the tool face and the sheet surface "
        "it acts on (mm). The die is below the sheet (z <= 0), punch "
        "and blank holder above (z >= thickness).");
      prm.declare_entry(
        "Stroke",
        str(d.stroke),
        Double(0),
        "Total tool travel (mm). The punch travel ends the run.");
      prm.declare_entry(
        "Speed",
        str(d.speed),
        Double(0),
        "Tool speed (mm/s), moving in -z. Only the punch moves.");
      prm.declare_entry("Friction coefficient",
                        str(d.friction_coefficient),
                        Double(0),
                        "Coulomb friction coefficient mu (-).");
      prm.declare_entry(
        "Penalty factor",
        str(d.penalty_factor),
        Double(0),
        "Fixed contact penalty for this tool (N/mm^3, contact pressure "
        "per mm of penetration); 0 takes Contact/Penalty factor.");
      prm.declare_entry(
        "Allowed penetration",
        str(d.allowed_penetration),
        Double(0),
        "Adaptive penalty: allowed penetration delta into this tool (mm); "
        "0 takes Contact/Allowed penetration.");
      prm.leave_subsection();
    }

    void Tool::parse(ParameterHandler &prm)
    {
      prm.enter_subsection(name);
      enabled              = prm.get_bool("Enabled");
      shape                = prm.get("Shape");
      diameter             = prm.get_double("Diameter");
      length               = prm.get_double("Length");
      width                = prm.get_double("Width");
      corner_radius        = prm.get_double("Corner radius");
      profile_radius       = prm.get_double("Profile radius");
      gap                  = prm.get_double("Gap");
      stroke               = prm.get_double("Stroke");
      speed                = prm.get_double("Speed");
      friction_coefficient = prm.get_double("Friction coefficient");
      penalty_factor       = prm.get_double("Penalty factor");
      allowed_penetration  = prm.get_double("Allowed penetration");
      prm.leave_subsection();
    }

    void Tool::validate() const
    {
      if (!enabled)
        return;
      const std::string e = "Tools/" + name + "/";
      if (shape == "round" && name != "Blank holder" && name != "Die")
        require(diameter > 0, e + "Diameter", "must be positive (mm)");
      if (shape == "round")
        require(profile_radius <= 0.5 * diameter || name != "Punch",
                e + "Profile radius",
                "must not exceed half the Diameter");
      if (shape == "rounded rectangle")
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

    void Tools::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Tools");
      Tool p{"Punch", true, "round", 40, 40, 40, 8, 8, 0, 15, 1, 0.1, 0, 0};
      Tool d{"Die", true, "round", 42.5, 42.5, 42.5, 8, 8, 0, 0, 0, 0.1, 0, 0};
      Tool b{"Blank holder",
             true,
             "round",
             58.5,
             0,
             0,
             0,
             0,
             0.05,
             0,
             0,
             0.1,
             0,
             0};
      Tool::declare(prm, p);
      Tool::declare(prm, d);
      Tool::declare(prm, b);
      prm.leave_subsection();
    }

    void Tools::parse(ParameterHandler &prm)
    {
      punch.name        = "Punch";
      die.name          = "Die";
      blank_holder.name = "Blank holder";
      prm.enter_subsection("Tools");
      punch.parse(prm);
      die.parse(prm);
      blank_holder.parse(prm);
      prm.leave_subsection();
    }

    void Tools::validate() const
    {
      punch.validate();
      die.validate();
      blank_holder.validate();
      require(punch.enabled, "Tools/Punch/Enabled", "the punch drives the run");
      require(punch.speed > 0, "Tools/Punch/Speed", "must be positive (mm/s)");
      require(punch.stroke > 0, "Tools/Punch/Stroke", "must be positive (mm)");
    }

    // ----------------------------------------------------------------- Contact
    void Contact::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry(
        "Penalty strategy",
        "fixed",
        Selection("fixed|adaptive|adaptive-strict|augmented-lagrangian"),
        "How penalty factors are chosen. fixed: 'Penalty factor' (or the "
        "tool's own) times the nodal contact area. adaptive: per contact "
        "pair and Newton iteration from the current system, so that the "
        "penetration is about 'Allowed penetration' (doc/theory.md). "
        "adaptive-strict: adaptive, and a converged step with a penetration "
        "above the allowed one is solved again with those factors scaled up. "
        "augmented-lagrangian: Uzawa updates of a multiplier per pair on "
        "the factors of 'Augmented Lagrangian penalty', the step re-solved "
        "until no node is deeper than 'Allowed penetration'.");
      prm.declare_entry(
        "Augmented Lagrangian penalty",
        "fixed",
        Selection("fixed|adaptive"),
        "augmented-lagrangian: the factors the Uzawa updates run on, "
        "fixed ('Penalty factor') or adaptive (as strategy adaptive).");
      prm.declare_entry(
        "Penalty factor",
        "1e5",
        Double(),
        "Fixed penalty (N/mm^3): contact pressure per mm of "
        "penetration. Each node gets this times its contact area.");
      prm.declare_entry("Allowed penetration",
                        "1e-3",
                        Double(),
                        "delta (mm): penetration the adaptive strategies aim "
                        "at (adaptive) or bound (adaptive-strict).");
      prm.declare_entry("Lower bound",
                        "1e-3",
                        Double(0),
                        "Adaptive: eps_k >= this * K_kk/dt, K_kk the tangent "
                        "diagonal of the node along the tool normal (-).");
      prm.declare_entry("Upper bound",
                        "1e4",
                        Double(0),
                        "Adaptive: eps_k <= this * K_kk/dt (-).");
      prm.declare_entry(
        "Adaptive estimate",
        "force",
        Selection("force|projection"),
        "projection: eps_k = n.(r + K dv)_k / delta, the published method "
        "with the node moved to penetration delta (dv) through the tangent "
        "K; force: its limit dv -> 0, eps_k = n.r_k / delta, the normal "
        "force the node carries divided by delta. In the flow formulation "
        "the tangent of rigid zones is a cutoff viscosity, not a stiffness, "
        "and projection overestimates by orders of magnitude "
        "(doc/contact.md).");
      prm.declare_entry(
        "Target fraction",
        "1",
        Double(0.01, 1),
        "Adaptive estimates aim at this fraction of 'Allowed penetration' "
        "(-). Below 1, adaptive-strict needs fewer re-solves, since fewer "
        "nodes end a step deeper than allowed.");
      prm.declare_entry(
        "Damping",
        "10",
        Double(1),
        "Adaptive: a factor may change by at most this ratio "
        "per estimate; the first estimate starts from the fixed "
        "penalty (-).");
      prm.declare_entry(
        "Freeze factors",
        "true",
        Bool(),
        "Adaptive: stop updating the factors in a step once the "
        "contact set is unchanged between two iterations.");
      prm.declare_entry("Max status flips",
                        "4",
                        Integer(1),
                        "Contact status changes of one node in one step after "
                        "which its status is locked for the rest of the step.");
      prm.declare_entry(
        "Max strict passes",
        "5",
        Integer(0),
        "adaptive-strict and augmented-lagrangian: re-solves of "
        "one step at most; a step still deeper than allowed "
        "after them is kept and reported in history.csv.");
      prm.declare_entry("Friction regularisation velocity",
                        "1e-3",
                        Double(),
                        "v0 (mm/s) of the friction law f_t = -mu p (2/pi) "
                        "atan(|v_t|/v0) v_t/|v_t|.");
      prm.declare_entry(
        "Search distance",
        "1",
        Double(),
        "Sheet nodes farther than this from a tool (mm) are not "
        "checked for contact with it in the current step.");
      prm.leave_subsection();
    }

    void Contact::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      penalty_strategy    = prm.get("Penalty strategy");
      al_penalty          = prm.get("Augmented Lagrangian penalty");
      penalty_factor      = prm.get_double("Penalty factor");
      allowed_penetration = prm.get_double("Allowed penetration");
      lower_bound         = prm.get_double("Lower bound");
      upper_bound         = prm.get_double("Upper bound");
      freeze              = prm.get_bool("Freeze factors");
      adaptive_estimate   = prm.get("Adaptive estimate");
      damping             = prm.get_double("Damping");
      target_fraction     = prm.get_double("Target fraction");
      max_status_flips    = prm.get_integer("Max status flips");
      max_strict_passes   = prm.get_integer("Max strict passes");
      regularisation_velocity =
        prm.get_double("Friction regularisation velocity");
      search_distance = prm.get_double("Search distance");
      prm.leave_subsection();
    }

    void Contact::validate() const
    {
      require(penalty_strategy != "augmented-lagrangian" ||
                max_strict_passes > 0,
              "Contact/Max strict passes",
              "must be at least 1 for augmented-lagrangian (its Uzawa "
              "updates are the passes)");
      require(penalty_factor > 0,
              "Contact/Penalty factor",
              "must be positive (N/mm^3), got " + str(penalty_factor));
      require(allowed_penetration > 0,
              "Contact/Allowed penetration",
              "must be positive (mm), got " + str(allowed_penetration));
      require(upper_bound > lower_bound,
              "Contact/Upper bound",
              "must exceed Contact/Lower bound");
      require(regularisation_velocity > 0,
              "Contact/Friction regularisation velocity",
              "must be positive (mm/s)");
      require(search_distance > 0,
              "Contact/Search distance",
              "must be positive (mm)");
    }

    // ----------------------------------------------------------- Time stepping
    void TimeStepping::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      prm.declare_entry(
        "Time step",
        "0.25",
        Double(),
        "Time step (s). With the punch speed it sets the punch travel "
        "per step; the run ends when the punch stroke is reached.");
      prm.leave_subsection();
    }

    void TimeStepping::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      time_step = prm.get_double("Time step");
      prm.leave_subsection();
    }

    void TimeStepping::validate() const
    {
      require(time_step > 0,
              "Time stepping/Time step",
              "must be positive (s), got " + str(time_step));
    }

    // -------------------------------------------------------- Nonlinear solver
    void NonlinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Max iterations",
                        "60",
                        Integer(1),
                        "Newton iterations per step before the step fails.");
      prm.declare_entry(
        "Residual tolerance",
        "1e-6",
        Double(0),
        "Converged when |r| <= tol * |f_int|, the norm of the element "
        "internal-force vectors (-) ...");
      prm.declare_entry("Correction tolerance",
                        "1e-6",
                        Double(0),
                        "... and |dv| <= tol * |v| (-), and the contact set is "
                        "unchanged.");
      prm.declare_entry(
        "Max line search steps",
        "6",
        Integer(0, 30),
        "Trial step lengths per Newton iteration: regula falsi on the "
        "directional derivative dv.r(v + alpha dv) of the potential.");
      prm.declare_entry(
        "Picard iterations",
        "0",
        Integer(0),
        "Direct (secant) iterations at the start of every step.");
      prm.declare_entry(
        "Picard fallback",
        "true",
        Bool(),
        "When the line search fails, do three direct (secant) iterations, "
        "then return to Newton.");
      prm.declare_entry("Log iterations",
                        "false",
                        Bool(),
                        "Print one line per nonlinear iteration: residual, "
                        "correction, line-search factor, contact-set changes.");
      prm.leave_subsection();
    }

    void NonlinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      max_iterations        = prm.get_integer("Max iterations");
      residual_tolerance    = prm.get_double("Residual tolerance");
      correction_tolerance  = prm.get_double("Correction tolerance");
      max_line_search_steps = prm.get_integer("Max line search steps");
      picard_iterations     = prm.get_integer("Picard iterations");
      picard_fallback       = prm.get_bool("Picard fallback");
      log_iterations        = prm.get_bool("Log iterations");
      prm.leave_subsection();
    }

    void NonlinearSolver::validate() const
    {
      require(residual_tolerance > 0,
              "Nonlinear solver/Residual tolerance",
              "must be positive");
      require(correction_tolerance > 0,
              "Nonlinear solver/Correction tolerance",
              "must be positive");
    }

    // ----------------------------------------------------------- Linear solver
    void LinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry(
        "Type",
        "direct",
        Selection("direct|iterative"),
        "direct: sparse LU through Trilinos Amesos; iterative: a "
        "Krylov solver with ML algebraic multigrid.");
      prm.declare_entry(
        "Direct solver",
        "MUMPS",
        Selection("MUMPS|KLU"),
        "Amesos back end (MUMPS runs in parallel; KLU gathers the "
        "matrix on one rank).");
      prm.declare_entry("Iterative solver",
                        "GMRES",
                        Selection("GMRES|CG"),
                        "Krylov method (CG only for frictionless contact: the "
                        "friction tangent is not symmetric).");
      prm.declare_entry(
        "Tolerance",
        "1e-8",
        Double(0),
        "Relative residual tolerance of the iterative solver (-).");
      prm.declare_entry("Max iterations",
                        "2000",
                        Integer(1),
                        "Iteration limit of the iterative solver.");
      prm.declare_entry(
        "Condition estimate iterations",
        "0",
        Integer(0),
        "Diagnostics: after every linear solve, this many unpreconditioned "
        "CG iterations on the system matrix give a Lanczos estimate of its "
        "condition number (history.csv column condition_estimate; a lower "
        "bound, meaningful for symmetric systems, i.e. without friction). "
        "0: off.");
      prm.leave_subsection();
    }

    void LinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type                 = prm.get("Type");
      direct_solver        = prm.get("Direct solver");
      iterative_solver     = prm.get("Iterative solver");
      tolerance            = prm.get_double("Tolerance");
      max_iterations       = prm.get_integer("Max iterations");
      condition_iterations = prm.get_integer("Condition estimate iterations");
      prm.leave_subsection();
    }

    void LinearSolver::validate() const
    {
      require(tolerance > 0 && tolerance < 1,
              "Linear solver/Tolerance",
              "must lie in (0, 1)");
    }

    // ------------------------------------------------------------------ Output
    void Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry(
        "Output directory",
        "results/cup-drawing",
        Anything(),
        "Folder for parameters.prm, history.csv and the VTU/PVTU/PVD "
        "files; created if missing.");
      prm.declare_entry(
        "Output interval",
        "5",
        Integer(0),
        "Write VTU every this many steps (and the last step); 0: never.");
      prm.declare_entry(
        "Wall time in history",
        "true",
        Bool(),
        "Write measured wall times into history.csv (false gives "
        "reproducible files, e.g. for regression tests).");
      prm.leave_subsection();
    }

    void Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory            = prm.get("Output directory");
      interval             = prm.get_integer("Output interval");
      wall_time_in_history = prm.get_bool("Wall time in history");
      prm.leave_subsection();
    }

    void Output::validate() const
    {
      require(!directory.empty(),
              "Output/Output directory",
              "must not be empty");
    }

    // ------------------------------------------------------------------- Run
    void Run::declare(ParameterHandler &prm)
    {
      Geometry::declare(prm);
      Mesh::declare(prm);
      MeshRefinement::declare(prm);
      Material::declare(prm);
      Tools::declare(prm);
      Contact::declare(prm);
      TimeStepping::declare(prm);
      NonlinearSolver::declare(prm);
      LinearSolver::declare(prm);
      Output::declare(prm);
    }

    void Run::parse(ParameterHandler &prm)
    {
      geometry.parse(prm);
      mesh.parse(prm);
      refinement.parse(prm);
      material.parse(prm);
      tools.parse(prm);
      contact.parse(prm);
      time.parse(prm);
      nonlinear.parse(prm);
      linear.parse(prm);
      output.parse(prm);
    }

    void Run::validate() const
    {
      geometry.validate();
      mesh.validate();
      refinement.validate(mesh.layers);
      material.validate();
      tools.validate();
      contact.validate();
      time.validate();
      nonlinear.validate();
      linear.validate();
      output.validate();
      if (tools.die.enabled && tools.die.shape == "round" &&
          (geometry.blank_shape == "disk" ||
           geometry.blank_shape == "quarter disk"))
        require(
          geometry.blank_diameter > tools.die.diameter,
          "Geometry/Blank diameter",
          "must exceed Tools/Die/Diameter, or the blank falls through the die");
    }
  } // namespace parameters
} // namespace formsolve
