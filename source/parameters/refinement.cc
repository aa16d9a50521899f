#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/refinement.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<Indicator> indicator_names{{"none", Indicator::none},
                                              {"kelly", Indicator::kelly}};
    } // namespace

    void MeshRefinement::declare(Declarations &d)
    {
      const Subsection s(d, "Mesh refinement");
      d.add(
        "Interval",
        interval,
        whole_number(0),
        "Adapt the mesh before step 1 and then every this many steps "
        "(steps); 0 switches adaptive refinement off. Level 0 is the initial "
        "mesh (Mesh/Planform refinements): refinement never coarsens below "
        "it, so choose a coarse initial mesh and refine near the radii.");
      d.add(
        "Punch level",
        punch_level,
        whole_number(0, 6),
        "Refinement level of blank cells within 'Band width' of the punch "
        "profile radius (levels above the initial mesh; 0: no refinement).");
      d.add("Die level",
            die_level,
            whole_number(0, 6),
            "As 'Punch level', for the die profile radius.");
      d.add("Blank holder level",
            holder_level,
            whole_number(0, 6),
            "As 'Punch level', for the blank-holder radius.");
      d.add("Band width",
            band_width,
            number("mm", 0),
            "Cells whose centre, less half the size of the initial cell they "
            "came from, lies within this distance (mm) of a tool's "
            "profile-radius arc, in the current configuration, are refined to "
            "that tool's level; make it cover the material that reaches the "
            "radius within 'Interval' steps.");
      d.add("Coarsening factor",
            coarsen_factor,
            number("-", 1),
            "Cells refined for a radius are coarsened once their centre is "
            "farther than this times 'Band width' from it (-): hysteresis, so "
            "cells do not flip between levels.");
      d.add(
        "Coarsening shape tolerance",
        shape_tolerance,
        number("mm", 0),
        "A family of cells is coarsened only if the coarse cell keeps the "
        "sheet's current shape: every vertex of the family within this "
        "distance (mm) of the coarse cell's (multilinear) surface. A "
        "coarsening that moves the sheet changes its volume and its contact "
        "with the tools, and the punch force jumps in the next step.");
      d.add("Indicator",
            indicator,
            indicator_names,
            "Solution-based criterion, combined with the radius bands: kelly "
            "refines the cells with the largest jumps of the velocity gradient "
            "(KellyErrorEstimator, current configuration) and coarsens those "
            "with the smallest.");
      d.add("Indicator level",
            indicator_level,
            whole_number(0, 6),
            "Highest level the indicator refines to.");
      d.add("Refine fraction",
            refine_fraction,
            number("-", 0, 1),
            "Indicator: fraction of the cells refined (-).");
      d.add("Coarsen fraction",
            coarsen_fraction,
            number("-", 0, 1),
            "Indicator: fraction of the cells coarsened (-).");
      d.add("Minimum layers at radii",
            min_layers,
            whole_number(1, 256),
            "Element layers through the thickness needed where the sheet bends "
            "(the bending test: 4 layers of Q1 give the limit moment within 2 "
            "%); every non-zero tool level must reach it.");
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
