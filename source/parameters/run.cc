#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/parameters/plausibility.h>
#include <formsolve/parameters/require.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    void Run::declare(Declarations &d)
    {
      geometry.declare(d);
      mesh.declare(d);
      refinement.declare(d);
      material.declare(d);
      tools.declare(d);
      contact.declare(d);
      time.declare(d);
      nonlinear.declare(d);
      linear.declare(d);
      split.declare(d);
      trimming.declare(d);
      springback.declare(d);
      output.declare(d);
    }

    void Run::complete()
    {
      material.read_flow_curve(); // Siebel's estimate may need it
      if (tools.holder_force_by_siebel)
        {
          const auto  s    = siebel(*this);
          const auto &hold = tools.blank_holder;
          require(s.applies || geometry.blank_shape != BlankShape::round ||
                    hold.shape != ToolShape::round ||
                    geometry.blank_diameter > hold.diameter,
                  "Geometry/Blank diameter",
                  "(" + str(geometry.blank_diameter) +
                    " mm) is not larger than the blank holder's opening "
                    "(Tools/Blank holder/Diameter = " +
                    str(hold.diameter) +
                    " mm): there is no flange for the holder"
                    " (Force = siebel) to press" +
                    (geometry.blank_diameter < 1 ? "; lengths are in mm, not m"
                                                 : ""));
          require(s.applies,
                  "Tools/Blank holder/Force",
                  "siebel needs a round blank larger than a round holder "
                  "opening and a round punch; give the force in N");
          tools.holder_force = ForceCurve::constant(s.force);
        }
    }

    namespace
    {
      /// Half sizes of a tool's outline along x and y (mm); infinite for
      /// flat tools.
      std::array<double, 2> half_sizes(const Tool &t)
      {
        if (t.shape == ToolShape::round)
          return {{0.5 * t.diameter, 0.5 * t.diameter}};
        if (t.shape == ToolShape::rounded_rectangle)
          return {{0.5 * t.length, 0.5 * t.width}};
        const double inf = std::numeric_limits<double>::infinity();
        return {{inf, inf}};
      }

      /// MemAvailable of /proc/meminfo (bytes), 0 if unknown.
      double available_memory()
      {
        std::ifstream meminfo("/proc/meminfo");
        std::string   key, unit;
        double        kb = 0;
        while (meminfo >> key >> kb >> unit)
          if (key == "MemAvailable:")
            return kb * 1024;
        return 0;
      }

      /// Cells of the initial mesh, before it is built (0: unknown, gmsh).
      double initial_cells(const Geometry &g, const Mesh &m)
      {
        if (model::space_dimension(g.model) == 2)
          return std::ldexp(2., m.refinements) * m.layers;
        double coarse = 0;
        if (g.blank_shape == BlankShape::round)
          coarse = g.model == model::Model::quarter ? 3
                   : g.model == model::Model::half  ? 4
                                                    : 5;
        else if (g.blank_shape == BlankShape::rectangle)
          {
            const double lx = model::symmetric_in_x(g.model)
                                ? 0.5 * g.blank_length
                                : g.blank_length;
            const double ly =
              model::symmetric_in_y(g.model) && g.model != model::Model::slice
                ? 0.5 * g.blank_width
                : g.blank_width;
            const double h = std::min(lx, ly);
            coarse         = std::max(1., std::round(lx / h)) *
                     std::max(1., std::round(ly / h));
          }
        return coarse * std::ldexp(1., 2 * m.refinements) * m.layers;
      }

      /// Peak memory per DoF of a run with this linear solver (bytes) and
      /// the setting it stands for: above the largest measured at 0.19-1.04M
      /// DoFs (doc/performance.md, "Memory of a run").
      std::pair<double, std::string> memory_per_dof(const Run &run)
      {
        const LinearSolver &l = run.linear;
        const bool          ldlt =
          l.symmetric_factorisation &&
          (run.symmetric_tangent() ||
           l.unsymmetric_factors == UnsymmetricFactors::symmetric_part);
        if (!l.out_of_core_directory.empty())
          return {9e3, "MUMPS, factors out of core"};
        // Single precision: 10.8 and 13.8 kB/DoF measured at 187k and 262k
        // DoFs on 2 ranks (doc/performance.md, "Single-precision factors").
        if (ldlt || l.factor_precision == FactorPrecision::single_precision)
          return {15e3,
                  ldlt ? "MUMPS LDL^T in core"
                       : "MUMPS single-precision factors in core"};
        return {19e3, "MUMPS LU in core"};
      }
    } // namespace

    bool Run::symmetric_tangent() const
    {
      for (const Tool *t : {&tools.punch, &tools.die, &tools.blank_holder})
        if (t->enabled && t->friction_coefficient != 0)
          return false;
      return true;
    }

    namespace
    {
      /// Every tool's shape and placement against the model.
      void check_tool_shapes(const Run &run)
      {
        const bool section = model::space_dimension(run.geometry.model) == 2;
        for (const auto &t : run.tools.additional)
          t.validate(section,
                     model::symmetric_in_x(run.geometry.model),
                     model::symmetric_in_y(run.geometry.model));
        std::vector<const Tool *> all = {&run.tools.punch,
                                         &run.tools.die,
                                         &run.tools.blank_holder};
        for (const auto &t : run.tools.additional)
          all.push_back(&t);
        for (const Tool *t : all)
          {
            require(!section || !t->enabled ||
                      t->shape != ToolShape::rounded_rectangle,
                    "Tools/" + t->name + "/Shape",
                    "must be round, flat or mesh (a profile in the section) "
                    "for a 2-D Geometry/Model (axisymmetric, plane strain)");
            require(!section || !t->enabled || t->shape != ToolShape::mesh ||
                      (t->mesh_offset[0] == 0 && t->mesh_offset[1] == 0),
                    "Tools/" + t->name + "/Mesh offset",
                    "a 2-D model (axisymmetric, plane strain) moves a profile "
                    "along z only (give 0, 0, z)");
          }
      }

      /// The outlines of punch, die and holder must fit together.
      /// Draw beads act between die and holder: a holder must close on
      /// them.
      void check_draw_beads(const Run &run)
      {
        const Tools &tools = run.tools;
        for (const auto &bead : tools.draw_beads.beads)
          {
            const std::string e = "Tools/Draw beads/" + bead.name + "/";
            require(tools.blank_holder.enabled && tools.die.enabled,
                    e + "Line",
                    "a draw bead acts between die and blank holder: enable "
                    "both (Tools/Die/Enabled, Tools/Blank holder/Enabled)");
            require(tools.holder_control != HolderControl::gap ||
                      tools.blank_holder.gap < bead.height,
                    e + "Height",
                    "(" + str(bead.height) +
                      " mm): the holder stays at Tools/Blank holder/Gap = " +
                      str(tools.blank_holder.gap) +
                      " mm above the sheet, so the bead would never "
                      "penetrate it; the height must exceed the gap");
          }
      }

      void check_outlines(const Run &run)
      {
        const Tools &tools = run.tools;
        if (tools.die.enabled && tools.die.shape == ToolShape::round &&
            run.geometry.model == model::Model::plane_strain)
          require(run.geometry.blank_length > tools.die.diameter,
                  "Geometry/Blank length",
                  "(" + str(run.geometry.blank_length) +
                    " mm) must exceed Tools/Die/Diameter (" +
                    str(tools.die.diameter) +
                    " mm, the die opening across the section), or the strip "
                    "falls through the die");
        if (tools.die.enabled && tools.die.shape == ToolShape::round &&
            run.geometry.blank_shape == BlankShape::round)
          require(run.geometry.blank_diameter > tools.die.diameter,
                  "Geometry/Blank diameter",
                  "(" + str(run.geometry.blank_diameter) +
                    " mm) must exceed Tools/Die/Diameter (" +
                    str(tools.die.diameter) +
                    " mm), or the blank falls through the die" +
                    (run.geometry.blank_diameter < 1
                       ? "; lengths are in mm, not m"
                       : ""));
        const double t0         = run.geometry.thickness;
        const auto   punch_half = half_sizes(tools.punch),
                   die_half     = half_sizes(tools.die),
                   holder_half  = half_sizes(tools.blank_holder);
        if (tools.die.enabled && tools.punch.has_outline() &&
            tools.die.has_outline())
          for (unsigned int a = 0; a < 2; ++a)
            {
              std::ostringstream what;
              what << "the punch (half size " << punch_half[a]
                   << " mm) does not fit into the die opening (half size "
                   << die_half[a]
                   << " mm): the clearance must be positive; a clearance "
                      "below the sheet thickness (Geometry/Thickness = "
                   << t0 << " mm) irons the wall and gets a warning";
              require(die_half[a] - punch_half[a] > 0,
                      tools.punch.shape == ToolShape::round
                        ? "Tools/Punch/Diameter"
                        : "Tools/Punch/Length",
                      what.str());
            }
        if (tools.blank_holder.enabled && tools.blank_holder.has_outline() &&
            tools.die.enabled && tools.die.has_outline())
          for (unsigned int a = 0; a < 2; ++a)
            require(holder_half[a] >= die_half[a],
                    "Tools/Blank holder/Diameter",
                    "the holder's opening (" + str(2 * holder_half[a]) +
                      " mm) lies inside the die opening "
                      "(Tools/Die/Diameter = " +
                      str(2 * die_half[a]) +
                      " mm): it would press the sheet into the die");
      }

      /// Refuse meshes the machine cannot hold, before building them.
      void check_memory(const Run &run)
      {
        const double cells = initial_cells(run.geometry, run.mesh);
        if (cells <= 0)
          return;
        const double dim  = model::space_dimension(run.geometry.model);
        const double dofs = dim * cells * std::pow(run.mesh.degree, dim) *
                            (1 + 1. / run.mesh.layers);
        const auto [per_dof, setting] = memory_per_dof(run);
        const double needed = per_dof * dofs, available = available_memory();
        std::ostringstream what;
        what << "gives about " << cells << " cells and " << dofs
             << " DoFs, which need about " << needed / 1e9 << " GB ("
             << per_dof / 1e3 << " kB per DoF with " << setting
             << "), more than 80 % of the " << available / 1e9
             << " GB available; lower Mesh/Planform refinements or "
                "Mesh/Layers through thickness, or set Linear "
                "solver/Out-of-core directory";
        require(available == 0 || needed < 0.8 * available,
                "Mesh/Planform refinements",
                what.str());
      }
    } // namespace

    void Run::validate() const
    {
      geometry.validate();
      mesh.validate();
      refinement.validate(mesh.layers);
      material.validate();
      tools.validate();
      tools.draw_beads.validate(model::space_dimension(geometry.model) == 2);
      contact.validate();
      time.validate();
      nonlinear.validate();
      linear.validate();
      split.validate();
      trimming.validate();
      springback.validate();
      output.validate();

      check_tool_shapes(*this);
      require(geometry.model != model::Model::axisymmetric ||
                !material.anisotropy.planar(),
              material.anisotropy.criterion == YieldCriterion::yld2004_18p
                ? "Material/Yld2004-18p C1"
              : material.anisotropy.calibration == HillCalibration::r_values
                ? "Material/R-values"
                : "Material/Yield stress ratios",
              "planar anisotropy (" + material.anisotropy.describe() +
                ") varies around the cup, which an axisymmetric section "
                "cannot represent: " +
                (material.anisotropy.criterion == YieldCriterion::yld2004_18p
                   ? std::string("use Hosford (isotropic) here, or ")
                   : std::string("give one normal r-value here, or ")) +
                "use Geometry/Model = quarter (earing needs a 3-D model)");
      require(!output.revolved_copy ||
                geometry.model == model::Model::axisymmetric,
              "Output/Revolved copy",
              "is only available for Geometry/Model = axisymmetric");
      require(time.end_of_run != EndOfRun::holder_release ||
                (tools.blank_holder.enabled &&
                 tools.blank_holder.has_outline()),
              "Time stepping/End of run",
              "'holder release' needs an enabled blank holder with an "
              "opening (Shape round or rounded rectangle)");
      require(time.end_of_run != EndOfRun::draw_through ||
                (tools.die.enabled && tools.die.has_outline()),
              "Time stepping/End of run",
              "'draw-through' needs an enabled die with an opening (Shape "
              "round or rounded rectangle)");
      check_outlines(*this);
      check_draw_beads(*this);
      check_trimming(*this);
      check_springback(*this);
      check_memory(*this);
    }
  } // namespace parameters
} // namespace formsolve
