// The ductile-fracture integrals averaged through the thickness over each
// column of elements, as the constants of Oyane's criterion were calibrated
// (section-averaged fracture strains; doc/theory.md, section 11a).
//
// A column is a finest planform footprint of the sheet mesh: the blank is an
// extruded planform with the layers along every cell's last reference axis,
// and refinement splits a cell's footprint into children, so a cell's
// footprint is its coarse cell's planform with the planform bits of its
// child indices. The column through a finest footprint holds every cell
// whose footprint contains it, in any layer, whatever its level (hanging
// nodes included); its average is sum(I_cell h_cell)/sum(h_cell), with
// I_cell the cell's volume average and h_cell its reference height.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <formsolve/material/damage.h>
#include <formsolve/state/state.h>

#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    template <int dim>
    struct ColumnMaximum
    {
      double             value = 0; // largest column average
      dealii::Point<dim> location;  // its column's current centre (mm)
    };

    template <int dim>
    struct ColumnDamage
    {
      ColumnMaximum<dim> oyane;            // I (-)
      ColumnMaximum<dim> cockcroft_latham; // W / C_crit (0: C_crit unset)
      /// Largest sum of reference heights in a column over the sheet
      /// thickness, minus 1: 0 when every column is complete.
      double height_error = 0;
    };

    template <int dim>
    class ThroughThicknessDamage
    {
    public:
      /// Measures the state (collective); the result is valid on every rank.
      /// With @p cell_values, also the deciding criterion's largest column
      /// average through each locally owned cell (cell_values()).
      ColumnDamage<dim> measure(const state::State<dim>        &state,
                                const material::DamageCriteria &damage,
                                const bool                      cell_values);

      /// By active cell index; 0 on cells of other ranks.
      const dealii::Vector<float> &cell_values() const { return cells; }

    private:
      dealii::Vector<float> cells;
    };
  } // namespace postprocess
} // namespace formsolve
