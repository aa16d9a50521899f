// What the formed sheet looks like to a forming engineer: nodal thickness
// measured from the bottom to the top surface along the mid-surface normal,
// thinning, major and minor true strains of the mid-surface, the forming
// limit zone, and the flange draw-in (doc/theory.md, section 11).
//
// The sheet is a set of node columns through the thickness, identified by
// their reference planform position (R in axisymmetry, (X, Y) in 3-D). Each
// rank measures its surface nodes and the cells cut by the reference
// mid-plane and sends each record to the rank that owns its column
// (column_owner.h); the owners assemble the columns, and the summary follows
// by reductions. No rank holds the whole sheet, except rank 0 when sheet.csv
// is written.
#pragma once

#include <deal.II/base/point.h>

#include <formsolve/material/damage.h>
#include <formsolve/material/forming_limit.h>
#include <formsolve/postprocess/column_owner.h>
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

      /// Measures the sheet of @p state (collective), once per step: a
      /// second call for the same step and mesh returns at once. The summary
      /// is valid on every rank; each rank holds the columns it owns.
      void measure(const state::State<dim>        &state,
                   const material::DamageCriteria &damage);

      const SheetSummary<dim> &summary() const { return sum; }
      /// The columns this rank owns, in the order of their keys.
      const std::vector<SheetColumn<dim>> &columns() const { return cols; }
      const material::FormingLimit        &forming_limit() const { return flc; }

      /// Every column, in the order of their keys, on rank 0 (collective;
      /// empty elsewhere): for the files written at output steps.
      std::vector<SheetColumn<dim>> gathered_columns(const MPI_Comm comm) const;

      /// Nodal fields thickness, thinning, major_strain, minor_strain,
      /// safety_zone for the VTU files (collective; valid until the next
      /// call).
      std::vector<NodalScalar> nodal_fields(const state::State<dim> &state);

      /// sheet.csv (one row per column) and flc.csv (the limit curve),
      /// written by rank 0 (collective).
      void write_csv(const MPI_Comm     comm,
                     const std::string &directory,
                     const std::string &name = "sheet.csv") const;

      /// The planform keys of columns().
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

      /// Record kinds in the flat vectors sent to a column's owner, each
      /// starting with its key: a surface or rim node (side 0 bottom, 1 top,
      /// 2 rim; whether a tool presses on it; current position), a corner of
      /// a cell cut by the reference mid-plane (its mid-plane point, major,
      /// minor, normal), a cell's largest deciding damage at a corner.
      enum Kind
      {
        node_record,
        corner_record,
        damage_record
      };
      /// This rank's records, by the rank that owns each column; the corner
      /// keys of its cells cut by the mid-plane, in the order their corner
      /// records were sent.
      Outbox local_records(const state::State<dim>                 &state,
                           const material::DamageCriteria          &damage,
                           std::vector<std::array<Key, n_corners>> &mid) const;
      /// The node records of local_records().
      void node_records(const state::State<dim> &state, Outbox &out) const;
      /// cols and keys of the columns this rank owns from the records sent
      /// to it (source/postprocess/sheet_columns.cc); the keys of the corner
      /// records each rank sent, in order.
      void assemble_columns(const Outbox                             &received,
                            std::map<unsigned int, std::vector<Key>> &corners);
      /// Every column's thickness replaced by the mean of the centre
      /// thicknesses of the mid-surface cells at it (Q2 mid-edge columns,
      /// at no cell corner, keep their own): the cells' ranks ask the owners
      /// for their corners' thicknesses and send the centre's back.
      void cell_centre_thickness(
        const MPI_Comm                                  comm,
        const std::vector<std::array<Key, n_corners>>  &mid,
        const std::map<unsigned int, std::vector<Key>> &corners);
      /// The summary of all ranks' columns (collective; marks the rim where
      /// no rim nodes exist).
      SheetSummary<dim> summarise(const MPI_Comm comm);
      /// The rim radius and draw-in of the summary (collective).
      void rim_measures(const MPI_Comm comm, SheetSummary<dim> &s) const;
      /// The index in cols of @p k, or cols.size().
      std::size_t find(const Key &k) const;

      /// The step and number of DoFs last measured (measure() once a step).
      std::pair<unsigned int, dealii::types::global_dof_index> measured{~0u, 0};

      double t0;
      /// The blank's diagonal: its corner's angle from x (degrees).
      double                        diagonal;
      material::FormingLimit        flc;
      SheetSummary<dim>             sum;
      std::vector<SheetColumn<dim>> cols; // owned by this rank
      std::vector<Key>              keys; // of cols, increasing
      std::array<VectorType, 5>     fields;
    };
  } // namespace postprocess
} // namespace formsolve
