// What the formed sheet looks like to a forming engineer: nodal thickness
// measured from the bottom to the top surface along the mid-surface normal,
// thinning, major and minor true strains of the mid-surface, the forming
// limit zone, and the flange draw-in (doc/theory.md, section 11).
//
// The sheet is a set of node columns through the thickness, identified by
// their reference planform position (R in axisymmetry, (X, Y) in 3-D). Each
// rank measures its surface nodes and the cells cut by the reference
// mid-plane; rank 0 assembles the columns; the results per column go back to
// all ranks for the VTU fields.
#pragma once

#include <deal.II/base/point.h>

#include <formsolve/material/damage.h>
#include <formsolve/material/forming_limit.h>
#include <formsolve/postprocess/vtu_writer.h>
#include <formsolve/state/state.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    template <int dim>
    struct SheetColumn
    {
      double             reference_radius = 0; // R0 (mm)
      double             reference_angle  = 0; // degrees from x, 3-D
      dealii::Point<dim> mid;                  // current mid-surface point
      double             thickness = 0;        // mm
      double major = 0, minor = 0;   // true strains of the mid-surface
      double damage             = 0; // deciding criterion, column max
      material::SafetyZone zone = material::SafetyZone::safe;
      bool                 rim  = false; // on the blank's outer edge
      /// Tools press on both its surfaces (it may thin by being squeezed,
      /// as an ironed wall).
      bool squeezed = false;
      // Highest and lowest current coordinate along the last axis of the
      // column's surface nodes (mm): the cup height.
      double top = 0, bottom = 0;
    };

    template <int dim>
    struct SheetSummary
    {
      double             min_thickness = 0, min_thickness_radius = 0; // mm
      dealii::Point<dim> min_thickness_location;
      double             max_thinning   = 0; // % of t0
      double             max_thickening = 0; // % of t0, 100 (t_max/t0 - 1)
      /// 100 (1 - the largest ratio of a column's major strain to the
      /// FLC's at its minor strain) (%): negative past the curve.
      double flc_margin = 100;
      /// The column nearest the FLC (the margin's): reference radius and
      /// angle (degrees from x), current mid-surface point.
      double             flc_radius = 0, flc_angle = 0;
      dealii::Point<dim> flc_location;
      /// Lowest point of the sheet to the highest of its rim (mm).
      double cup_height   = 0;
      double blank_radius = 0; // largest reference radius
      /// Rim radius (current, mm) and draw-in R0 - r per direction: in 3-D
      /// x, the diagonal (a rectangular blank's corner, else 45 degrees) and
      /// y (NaN outside the modelled part); one value in axisymmetry.
      std::vector<double>                                rim_radius, draw_in;
      std::array<unsigned int, material::n_safety_zones> zone_count{};
    };

    template <int dim>
    class SheetMeasures
    {
    public:
      using Key = std::array<long long, dim - 1>;

      SheetMeasures(const parameters::Run &prm);

      /// Measures the sheet of @p state (collective). The summary is valid on
      /// every rank, the columns on rank 0.
      void measure(const state::State<dim>        &state,
                   const material::DamageCriteria &damage);

      const SheetSummary<dim>             &summary() const { return sum; }
      const std::vector<SheetColumn<dim>> &columns() const { return cols; }
      const material::FormingLimit        &forming_limit() const { return flc; }

      /// Nodal fields thickness, thinning, major_strain, minor_strain,
      /// safety_zone for the VTU files (collective; valid until the next
      /// call).
      std::vector<NodalScalar> nodal_fields(const state::State<dim> &state);

      /// sheet.csv (one row per column) and flc.csv (the limit curve), rank 0.
      void write_csv(const std::string &directory,
                     const std::string &name = "sheet.csv") const;

      /// The columns' planform keys (rank 0, in the order of columns()).
      const std::vector<Key> &column_keys() const { return keys; }

      /// The planform key of a reference position.
      static Key key(const dealii::Point<dim> &reference);
      /// Distance of two columns in the reference planform (mm).
      static double distance(const Key &a, const Key &b);

    private:
      /// Planform keys are reference positions in units of quantum (mm).
      static constexpr double quantum = 1e-7;
      /// Corners of a cell's face in the planform.
      static constexpr unsigned int n_corners = dim == 2 ? 2 : 4;

      /// One rank's measurements, flat vectors of doubles gathered on rank 0.
      /// nodes: key, side (0 bottom, 1 top, 2 rim), whether a tool presses
      /// on it, current position (dim);
      /// cells: corner keys, corner mid-plane points, major, minor, normal;
      /// damages: corner keys, largest deciding damage in the cell.
      struct Records
      {
        std::vector<double> nodes, cells, damages;
      };
      /// This rank's surface nodes, the cells cut by the reference mid-plane
      /// and every cell's damage.
      Records local_records(const state::State<dim>        &state,
                            const material::DamageCriteria &damage) const;
      /// The nodes part of local_records().
      std::vector<double> node_records(const state::State<dim> &state) const;
      /// Rank 0: cols and keys from the records of all ranks
      /// (source/postprocess/sheet_columns.cc).
      void assemble_columns(const std::vector<std::vector<double>> &nodes,
                            const std::vector<std::vector<double>> &cells,
                            const std::vector<std::vector<double>> &damages);
      /// Rank 0: every column's thickness replaced by the mean of the
      /// centre thicknesses of the mid-surface cells at it (Q2 mid-edge
      /// columns, at no cell corner, keep their own).
      void cell_centre_thickness(
        const std::vector<std::array<Key, n_corners>> &mid_cells);
      /// Rank 0: the summary of cols (marks the rim where no rim nodes
      /// exist).
      SheetSummary<dim> summarise();

      double t0;
      /// The blank's diagonal: its corner's angle from x (degrees).
      double                        diagonal;
      material::FormingLimit        flc;
      SheetSummary<dim>             sum;
      std::vector<SheetColumn<dim>> cols; // rank 0
      std::vector<Key>              keys; // of cols
      std::array<VectorType, 5>     fields;
    };
  } // namespace postprocess
} // namespace formsolve
