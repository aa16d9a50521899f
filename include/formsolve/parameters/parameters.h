// One struct per .prm subsection: declare, parse, validate.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    using dealii::ParameterHandler;

    /// Subsection "Geometry": the blank (sheet) before forming.
    struct Geometry
    {
      std::string blank_shape;     // disk | quarter disk | rectangle | quarter
                                   // rectangle | gmsh
      double      blank_diameter;  // mm
      double      blank_length;    // mm, full length along x
      double      blank_width;     // mm, full width along y
      double      thickness;       // mm
      std::string mesh_file;       // gmsh .msh or .geo (2-D planform)
      std::string symmetry_planes; // none | x | y | xy

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;

      /// Factor from the modelled part to the full part (4 for a quarter).
      double symmetry_factor() const;
      bool   symmetric_in_x() const; // plane x = 0 is a symmetry plane
      bool   symmetric_in_y() const; // plane y = 0 is a symmetry plane
    };

    /// Subsection "Mesh".
    struct Mesh
    {
      unsigned int degree;
      unsigned int layers;
      unsigned int refinements;

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Mesh refinement": adaptive refinement near tool radii and
    /// by an error indicator (p4est; levels count from the initial mesh).
    struct MeshRefinement
    {
      unsigned int interval;        // steps between adaptations, 0: off
      unsigned int punch_level;     // max level near the punch profile radius
      unsigned int die_level;       // ... die profile radius
      unsigned int holder_level;    // ... blank-holder profile radius
      double       band_width;      // mm from the radius arc, current config.
      double       coarsen_factor;  // coarsen beyond this * band width
      std::string  indicator;       // none | kelly
      unsigned int indicator_level; // max level the indicator may refine to
      double       refine_fraction, coarsen_fraction; // of the cells
      unsigned int min_layers; // element layers at the radii, at least

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      /// Needs Mesh/Layers through thickness.
      void validate(const unsigned int layers) const;
      bool enabled() const { return interval > 0; }
    };

    /// Subsection "Material": flow stress and the flow-formulation constants.
    struct Material
    {
      double strength_coefficient;  // K (MPa)
      double hardening_exponent;    // n
      double prestrain;             // eps_0
      double rate_sensitivity;      // m
      double reference_strain_rate; // 1/s
      double limiting_strain_rate;  // 1/s, rigid-zone cutoff
      double volumetric_penalty;    // alpha (-)

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// One subsection of "Tools" (Punch, Die, Blank holder).
    struct Tool
    {
      std::string name; // subsection name, also the history column prefix
      bool        enabled;
      std::string shape;          // round | rounded rectangle | flat
      double      diameter;       // mm (round)
      double      length;         // mm (rounded rectangle, along x)
      double      width;          // mm (rounded rectangle, along y)
      double      corner_radius;  // mm (rounded rectangle, in plane)
      double      profile_radius; // mm (fillet of the working edge)
      double      gap;            // mm, initial distance to the sheet surface
      double      stroke;         // mm, total travel (moving tools)
      double      speed;          // mm/s (moving tools)
      double      friction_coefficient;
      double      penalty_factor;      // N/mm^3; 0: use Contact/Penalty factor
      double      allowed_penetration; // mm; 0: use Contact/Allowed penetration

      static void declare(ParameterHandler &prm, const Tool &defaults);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Tools".
    struct Tools
    {
      Tool punch, die, blank_holder;

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Contact".
    struct Contact
    {
      std::string penalty_strategy;      // fixed | adaptive | adaptive-strict |
                                         // augmented-lagrangian
      std::string  al_penalty = "fixed"; // factors under Uzawa
      double       penalty_factor; // N/mm^3 (pressure per mm of penetration)
      double       allowed_penetration; // delta (mm)
      double       lower_bound;         // eps_k dt / K_kk, adaptive
      double       upper_bound;
      bool         freeze;              // keep eps once the contact set settles
      std::string  adaptive_estimate;   // force | projection
      double       damping;             // max change factor of eps per estimate
      double       target_fraction = 1; // estimates aim at this * delta
      unsigned int max_status_flips;    // then the pair's status is locked
      unsigned int max_strict_passes;   // strict / Uzawa re-solves per step
      double       regularisation_velocity; // mm/s, friction arctan law
      double       search_distance; // mm, nodes farther than this are skipped

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Time stepping".
    struct TimeStepping
    {
      double time_step; // s

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Nonlinear solver".
    struct NonlinearSolver
    {
      unsigned int max_iterations;
      double       residual_tolerance;
      double       correction_tolerance;
      unsigned int max_line_search_steps;
      unsigned int
           picard_iterations; // direct iterations at the start of a step
      bool picard_fallback;
      bool log_iterations;

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Linear solver".
    struct LinearSolver
    {
      std::string  type;             // direct | iterative
      std::string  direct_solver;    // MUMPS | KLU
      std::string  iterative_solver; // GMRES | CG
      double       tolerance;
      unsigned int max_iterations;
      unsigned int condition_iterations = 0; // Lanczos estimate, 0: off

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// Subsection "Output".
    struct Output
    {
      std::string  directory;
      unsigned int interval; // write VTU every N steps (0: never)
      bool         wall_time_in_history;

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      void        validate() const;
    };

    /// All subsections together.
    struct Run
    {
      Geometry        geometry;
      Mesh            mesh;
      MeshRefinement  refinement;
      Material        material;
      Tools           tools;
      Contact         contact;
      TimeStepping    time;
      NonlinearSolver nonlinear;
      LinearSolver    linear;
      Output          output;

      static void declare(ParameterHandler &prm);
      void        parse(ParameterHandler &prm);
      /// Cross-subsection checks; throws with a message naming the entries.
      void validate() const;
    };
  } // namespace parameters
} // namespace formsolve
