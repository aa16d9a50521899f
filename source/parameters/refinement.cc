#include <formsolve/parameters/choice.h>
#include <formsolve/parameters/refinement.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    namespace
    {
      const Choice<Indicator> indicator_names{{"none", Indicator::none},
                                              {"kelly", Indicator::kelly}};
    } // namespace

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
        "Coarsening shape tolerance",
        "1e-3",
        Double(0),
        "A family of cells is coarsened only if the coarse cell keeps the "
        "sheet's current shape: every vertex of the family within this "
        "distance (mm) of the coarse cell's (multilinear) surface. A "
        "coarsening that moves the sheet changes its volume and its contact "
        "with the tools, and the punch force jumps in the next step.");
      prm.declare_entry(
        "Indicator",
        "none",
        Selection(indicator_names.pattern()),
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
      shape_tolerance  = prm.get_double("Coarsening shape tolerance");
      indicator        = indicator_names.parse(prm.get("Indicator"));
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
      require(punch_level + die_level + holder_level > 0 ||
                indicator != Indicator::none,
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
  } // namespace parameters
} // namespace formsolve
