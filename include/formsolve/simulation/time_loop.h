// The time loop: set-up and scene checks, then per step: adapt the mesh when
// due, check the process events (blank-holder release, draw-through), solve
// the step, advance the state, measure the forming results (fracture,
// thickness, strains), write history, progress and output. The forming
// results and the run's closing files are in time_loop_results.cc.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <formsolve/material/damage.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/postprocess/contact_fields.h>
#include <formsolve/postprocess/earing.h>
#include <formsolve/postprocess/history_writer.h>
#include <formsolve/postprocess/progress.h>
#include <formsolve/postprocess/sheet_measures.h>
#include <formsolve/postprocess/statistics_table.h>
#include <formsolve/postprocess/through_thickness.h>
#include <formsolve/postprocess/tool_writer.h>
#include <formsolve/postprocess/vtu_writer.h>
#include <formsolve/refinement/mesh_refinement.h>
#include <formsolve/simulation/checkpoint.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/step_solver.h>
#include <formsolve/state/state.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace formsolve
{
  namespace simulation
  {
    using state::State;
    using state::VectorType;

    /// Summary of a finished run (for tests and benchmarks).
    struct RunSummary
    {
      unsigned int steps                   = 0;
      unsigned int newton_iterations       = 0;
      unsigned int linear_iterations       = 0;
      unsigned int matrix_assemblies       = 0; // tangent assemblies
      unsigned int factorisations          = 0; // numeric, direct solver
      double       factorisation_memory_mb = 0; // MUMPS, all ranks, largest
      double       factor_entries          = 0; // MUMPS, largest
      unsigned int cutbacks                = 0;
      /// Newton iterations of the first step on the coarser mesh
      /// (Nonlinear solver/First step start), not in newton_iterations.
      unsigned int coarse_start_iterations = 0;
      double       wall_time               = 0;
      double       newton_wall_time = 0; // spent inside Newton iterations
      double       n_dofs           = 0; // largest over the run
      double       dof_steps        = 0; // sum over steps of the DoFs
      double       peak_memory_kb   = 0; // peak resident set, all ranks
      double       peak_memory_kb_max_rank = 0; // the same, largest rank
      /// Peak resident set of the largest rank once the mesh, DoFs and
      /// matrix are set up, before the first factorisation.
      double setup_memory_kb_max_rank = 0;
      double peak_punch_force         = 0; // N, full part
      double peak_force_travel        = 0; // mm
      double max_penetration          = 0; // mm, over the run
      /// Ironing: the punch travel (mm) at which the wall was first
      /// squeezed between punch and die with more than 0.5 % of the punch
      /// force (-1: never), and the largest such force (N, full part).
      double ironing_travel = -1, max_ironing_force = 0;
      /// Punch travel at which the deciding fracture criterion first reached
      /// 1 by Material/Fracture measure (interpolated between steps), -1 if
      /// it did not.
      double      critical_stroke = -1;
      std::string fracture_location; // "r z" or "x y z" (mm)
      /// The same by each measure, with the running values of the loop
      /// (kept in checkpoints).
      struct Watch
      {
        double      stroke = -1;     // mm, -1: not reached
        std::string location;        // "r z" or "x y z" (mm)
        double      last        = 0; // value of the last step
        double      last_travel = 0; // mm
      };
      Watch       local, through_thickness;
      std::string end_reason;
      double      wall_before = 0; // s of wall time before a resume
    };

    template <int dim>
    class TimeLoop
    {
    public:
      TimeLoop(const parameters::Run &run, const dealii::ParameterHandler &prm);

      /// Set up, check the scene, create the output folder, run all steps;
      /// with @p resume, continue from the newest checkpoint instead. Throws
      /// with a clear message when a step fails at the minimum time step
      /// (after writing the output and a checkpoint of the last converged
      /// step).
      RunSummary run(const bool resume = false);

      /// Build the mesh and check the initial scene, then stop (--validate).
      void validate_scene();

    private:
      /// The mesh (new, or from the checkpoint), the output folder, the
      /// refinement towards the radii, the first output and the coarse
      /// start.
      void start(const bool resume, RunSummary &summary);
      void start_refinement(const bool resume);
      /// The next step, accounted in @p summary; a step that fails at the
      /// minimum time step leaves output and a checkpoint, then throws.
      solver::StepReport solve_step(RunSummary &summary);
      /// The converged step: state update, history.csv, the screen line.
      /// Whether the fracture criterion has reached 1.
      bool record_step(const solver::StepReport &report, RunSummary &summary);
      /// Ironing's first appearance on screen, its largest force in the
      /// summary.
      void note_ironing(const contact::ContactStatistics<dim> &s,
                        const double                           punch_force,
                        RunSummary                            &summary);
      void save_checkpoint(RunSummary &summary);
      /// Last output and checkpoint, summaries, report.
      void finish(RunSummary &summary);
      /// Wall time of the run, that before a resume included (s).
      double seconds() const
      {
        return *wall_before + std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - start_time)
                                .count();
      }

      void check_initial_scene();
      void prepare_output_directory();
      /// Adapt the mesh; logs a row of refinement.csv. Whether it changed.
      bool adapt();
      /// solution_<step> and tools_<step>
      /// (source/simulation/time_loop_output.cc).
      void write_output();
      /// How far the tools' unbounded faces and walls are drawn.
      tools::SurfaceExtent tool_extent() const;
      /// Holder release and draw-through; the reason to end the run, or "".
      std::string check_events();
      /// Nonlinear solver/First step start = coarser mesh: the first step
      /// solved on the coarser mesh, as the start of the real one.
      void start_from_coarser_mesh(RunSummary &summary);
      void write_summary(RunSummary &summary) const;
      /// Thickness, strains, zones, draw-in and damage maxima of the state.
      postprocess::FormingMeasures<dim> measure_forming();
      /// Whether the deciding criterion has reached 1 in this step; records
      /// the critical stroke in @p summary and says so.
      bool check_fracture(const postprocess::FormingMeasures<dim> &m,
                          RunSummary                              &summary);
      /// report/ by scripts/formsolve-report (rank 0; never fails the run).
      void make_report() const;
      /// The time loop's values for a checkpoint, and back (resume).
      Metadata loop_metadata(const RunSummary &summary) const;
      void     restore_loop(const Metadata &meta, RunSummary &summary);
      /// The complete parameter listing (what a checkpoint must match).
      std::string parameter_listing() const;

      const parameters::Run          &prm;
      const dealii::ParameterHandler &parameter_handler;
      MPI_Comm                        comm;
      dealii::ConditionalOStream      pcout;
      dealii::TimerOutput             timer;

      material::RigidViscoplastic                   material;
      material::DamageCriteria                      damage;
      State<dim>                                    state;
      state::HistoryUpdate<dim>                     history_update;
      solver::Assembler<dim>                        assembler;
      solver::StepSolver<dim>                       step_solver;
      refinement::RefinementCriteria<dim>           criteria;
      std::unique_ptr<postprocess::StatisticsTable> refinement_log;
      std::unique_ptr<postprocess::VtuWriter<dim>>  writer;
      std::unique_ptr<postprocess::ToolWriter<dim>> tool_writer;
      postprocess::ContactFields<dim>               contact_fields;
      postprocess::SheetMeasures<dim>               sheet;
      postprocess::ThroughThicknessDamage<dim>      column_damage;
      postprocess::EaringProfile earing; // 3-D round blanks, rank 0, at the end
      std::unique_ptr<const Checkpoint<dim>>           checkpoint;
      std::unique_ptr<postprocess::HistoryWriter<dim>> history;
      postprocess::Progress                            progress;
      std::chrono::steady_clock::time_point            start_time;
      const double *wall_before      = nullptr; // the summary's
      int           last_output_step = -1;
      unsigned int  refinement_rows  = 0;
    };
  } // namespace simulation
} // namespace formsolve
