// history.csv (the process) and solver.csv (how each step was solved, and
// the solution's checks): one row per converged step each, columns by name
// (documented in doc/user-guide.md, section 5).
#pragma once

#include <formsolve/contact/contact_statistics.h>
#include <formsolve/forming/step_solver.h>
#include <formsolve/postprocess/sheet_measures.h>
#include <formsolve/postprocess/statistics_table.h>
#include <formsolve/postprocess/through_thickness.h>
#include <formsolve/state/sheet_integrals.h>
#include <formsolve/state/state.h>

namespace formsolve
{
  namespace postprocess
  {
    /// What the forming engineer reads from a step: sheet thickness, strains,
    /// zones, draw-in (SheetMeasures) and the largest damage values.
    template <int dim>
    struct FormingMeasures
    {
      SheetSummary<dim>          sheet;
      state::HistoryMaximum<dim> oyane;             // I (-)
      state::HistoryMaximum<dim> cockcroft_latham;  // integral W (MPa)
      double            cockcroft_latham_ratio = 0; // W / C_crit, 0 unset
      ColumnDamage<dim> through_thickness;          // column averages
    };

    template <int dim>
    class HistoryWriter
    {
    public:
      /// Creates <Output directory>/history.csv and solver.csv (rank 0) with
      /// the columns of the tools of @p state.
      /// With @p keep_rows >= 0, a resumed run: the files keep that many rows.
      HistoryWriter(const state::State<dim> &state, const int keep_rows = -1);

      /// One row for the step just advanced. Forces are for the full part.
      void write(const state::State<dim>               &state,
                 const solver::StepReport              &report,
                 const contact::ContactStatistics<dim> &stats,
                 const FormingMeasures<dim>            &forming,
                 const double                           wall_time);

    private:
      /// history.csv: the tools' forces and positions.
      void set_tool_columns(const state::State<dim>               &state,
                            const contact::ContactStatistics<dim> &stats);
      /// solver.csv: how the step was solved and its checks.
      void set_solver_columns(const state::State<dim>               &state,
                              const solver::StepReport              &report,
                              const contact::ContactStatistics<dim> &stats);
      /// history.csv: thickness, strains, damage, draw-in, zones.
      void set_forming_columns(const state::State<dim>    &state,
                               const FormingMeasures<dim> &forming);

      StatisticsTable table, solver_table;
    };
  } // namespace postprocess
} // namespace formsolve
