// The time loop: set-up and scene checks, then per step: adapt the mesh when
// due, check the process events (blank-holder release, draw-through), solve
// the step, advance the state, measure the forming results (fracture,
// thickness, strains), write history, progress and output. The forming
// results and the run's closing files are in time_loop_results.cc.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/forming/step_solver.h>
#include <formsolve/material/damage.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/postprocess/contact_fields.h>
#include <formsolve/postprocess/earing.h>
#include <formsolve/postprocess/history_writer.h>
#include <formsolve/postprocess/progress.h>
#include <formsolve/postprocess/sheet_measures.h>
#include <formsolve/postprocess/split_watch.h>
#include <formsolve/postprocess/statistics_table.h>
#include <formsolve/postprocess/through_thickness.h>
#include <formsolve/postprocess/tool_writer.h>
#include <formsolve/postprocess/vtu_writer.h>
#include <formsolve/refinement/mesh_refinement.h>
#include <formsolve/simulation/checkpoint.h>
#include <formsolve/simulation/start_from.h>
#include <formsolve/springback/channel_measures.h>
#include <formsolve/springback/measure_points.h>
#include <formsolve/springback/release.h>
#include <formsolve/springback/ring_opening.h>
#include <formsolve/state/state.h>
#include <formsolve/trimming/trim_cells.h>

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
      /// The local solves of a non-quadratic criterion, all ranks: count,
      /// iterations, those over 6 iterations, the most one took.
      double local_solves = 0, local_iterations = 0, local_long_solves = 0;
      double local_most_iterations = 0;
      /// Peak resident set of the largest rank once the mesh, DoFs and
      /// matrix are set up, before the first factorisation.
      double setup_memory_kb_max_rank = 0;
      double peak_punch_force         = 0; // N, full part
      double peak_force_travel        = 0; // mm
      double max_penetration          = 0; // mm, over the run
      /// Ironing: the punch travel (mm) at which the wall was first
      /// squeezed between punch and die with more than 0.5 % of the punch
      /// force (-1: never), the largest such force (N, full part: the normal
      /// forces on the wall summed, which may exceed the axial punch force)
      /// and the largest pressure on the wall.
      double ironing_travel = -1, max_ironing_force = 0;
      double max_ironing_pressure = 0; // MPa, on the ironed wall
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
      /// The step failed at the minimum time step: the run ended there.
      bool   solver_failed = false;
      double wall_before   = 0; // s of wall time before a resume
    };

    template <int dim>
    class TimeLoop
    {
    public:
      TimeLoop(const parameters::Run &run, const dealii::ParameterHandler &prm);

      /// Set up, check the scene, create the output folder, run all steps;
      /// with @p resume, continue from the newest checkpoint instead. Every
      /// run that stops after its set-up leaves its closing files (last
      /// VTU, sheet.csv, run-summary.txt with end_reason, the report).
      /// Throws with a clear message when a step fails at the minimum time
      /// step without a split before it (after writing those files and a
      /// checkpoint of the last converged step), and passes on any other
      /// error after writing what rank 0 can write alone.
      RunSummary run(const bool resume = false);

      /// Build the mesh and check the initial scene, then stop (--validate).
      void validate_scene();

      /// report/ by scripts/formsolve-report (rank 0; never fails), if the
      /// run wrote its closing files. Called last, after every rank has
      /// left run(), also after an error every rank shares: the report
      /// takes seconds, which a rank waiting in error_exit must not wait.
      void make_report() const;

    private:
      /// The mesh (new, or from the checkpoint), the output folder, the
      /// refinement towards the radii, the first output and the coarse
      /// start.
      void start(const bool resume, RunSummary &summary);
      void start_refinement(const bool resume);
      /// The steps up to the end of the run; its reason in @p summary.
      void run_steps(RunSummary &summary);
      /// The next step, accounted in @p summary (converged or failed at the
      /// minimum time step).
      solver::StepReport solve_step(RunSummary &summary);
      /// The converged step: state update, history.csv, the split watch,
      /// the screen line.
      void record_step(const solver::StepReport &report, RunSummary &summary);
      /// The first occurrence of each split measure, said on screen.
      void announce_split(const std::vector<postprocess::SplitMeasure> &found);
      /// The punch travel at which the run stops after its split (infinite
      /// if it does not stop for it).
      double split_stop_travel() const;
      /// Why the run ended after the split, and after a failed step.
      std::string split_reason() const;
      std::string failure_reason(const solver::StepReport &report) const;
      /// Ironing's first appearance on screen, its largest force in the
      /// summary.
      void note_ironing(const contact::ContactStatistics<dim> &s,
                        const double                           punch_force,
                        RunSummary                            &summary);
      /// @p end: the run's end (after trimming and springback), which a
      /// next operation can start from (Geometry/Start from).
      void save_checkpoint(RunSummary &summary, const bool end = false);
      /// The part: a new blank, or the earlier run's (Geometry/Start from).
      void make_part();
      /// Whether a checkpoint is due after this step: by Output/Checkpoint
      /// interval, or by Checkpoint wall time on rank 0's clock.
      bool checkpoint_due() const;
      /// Last output and checkpoint, summaries, report.
      void finish(RunSummary &summary);
      /// Springback/Enabled: the release of the end of forming, its file
      /// and its lines on screen (source/simulation/time_loop_springback.cc).
      /// A release that fails is said, and the forming results stay.
      void spring_back();
      /// After the last step: the trim (Trimming; doc/trimming.md), its
      /// files and screen line (source/simulation/time_loop_trimming.cc).
      void trim();
      /// trimmed_<step>.pvtu and trim-outline.csv.
      void write_trimmed();
      /// The trimming lines of run-summary.txt ("" without it).
      std::string trimming_summary() const;
      /// Where the last step found its equilibrium: u - dt v.
      std::unique_ptr<model::CurrentMapping<dim>> start_configuration() const;
      /// The springback lines of run-summary.txt ("" without it).
      std::string springback_summary() const;
      /// The section's profile before and after (springback-profile.csv)
      /// and, for a plane-strain channel, its angles and curl.
      void measure_section(const springback::Release<dim> &release);
      /// springback-points.csv (rank 0): Springback/Measure points.
      void write_points() const;
      /// What the release's end state and result warrant a warning for.
      std::vector<std::string> springback_warnings() const;
      /// After an error past the first step: run-summary.txt, sheet.csv of
      /// the last converged step and the report, by rank 0 alone (the other
      /// ranks may not share the error); nothing collective.
      void close_after_error(RunSummary &summary, const std::string &error);
      /// Wall time of the run, that before a resume included (s).
      double seconds() const
      {
        return *wall_before + std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - start_time)
                                .count();
      }

      /// The scene before the first step: errors for a blank inside a tool
      /// or off the die and holder; warnings (scene_warnings) for a tool
      /// that can never touch the sheet and a mesh too coarse for the
      /// step or the bending.
      void        check_initial_scene();
      void        check_reach();
      void        check_resolution();
      std::string die_message() const;
      void        prepare_output_directory();
      /// Adapt the mesh; logs a row of refinement.csv. Whether it changed.
      bool adapt();
      /// solution_<step> and tools_<step> (once a step), and the revolved
      /// copy with it or, if @p last, with the last output only
      /// (source/simulation/time_loop_output.cc).
      void write_output(const bool last = false);
      /// How far the tools' unbounded faces and walls are drawn.
      tools::SurfaceExtent tool_extent() const;
      /// Holder release and draw-through; the reason to end the run, or "".
      /// Sets to_end.
      std::string check_events();
      /// The screen line of a converged step.
      void print_step(const solver::StepReport &report,
                      const double              force,
                      const double              penetration);
      /// Nonlinear solver/First step start = coarser mesh: the first step
      /// solved on the coarser mesh, as the start of the real one.
      void start_from_coarser_mesh(RunSummary &summary);
      /// The forming results of the run on screen: split, fracture,
      /// thickness, FLD zones, tools that never touched the sheet.
      void print_results(const RunSummary &summary);
      /// Memory statistics of all ranks (collective).
      void measure_memory(RunSummary &summary) const;
      /// run-summary.txt (rank 0).
      void write_summary(const RunSummary &summary) const;
      /// The split lines of run-summary.txt.
      std::string split_summary() const;
      /// The draw beads' lines of run-summary.txt.
      std::string bead_summary() const;
      /// Warnings of the run itself (tools that never touched the sheet).
      std::vector<std::string> run_warnings() const;
      /// Thickness, strains, zones, draw-in and damage maxima of the state.
      postprocess::FormingMeasures<dim> measure_forming();
      /// The deciding criterion's event if it has reached 1 in this step;
      /// records the critical stroke in @p summary and says so.
      postprocess::SplitEvent<dim>
      check_fracture(const postprocess::FormingMeasures<dim> &m,
                     RunSummary                              &summary);

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
      postprocess::SplitWatch<dim>                  split;
      postprocess::EaringProfile earing; // 3-D round blanks, rank 0, at the end
      std::unique_ptr<const Checkpoint<dim>>           checkpoint;
      std::unique_ptr<postprocess::HistoryWriter<dim>> history;
      postprocess::Progress                            progress;
      std::chrono::steady_clock::time_point            start_time;
      const double *wall_before      = nullptr; // the summary's
      int           last_output_step = -1;
      /// How far a run that ends by an event is from it (mm): the flange
      /// left on the die (draw-through) or under the holder (holder
      /// release); NaN for a run that ends at a travel. For the time left.
      double to_go           = 0;
      double last_checkpoint = 0;     // wall time of the last checkpoint (s)
      bool   split_said      = false; // the split announced on screen
      bool   report_due      = false; // the closing files are written
      /// Whether each tool has carried a force yet (a tool that never
      /// does is said at the end).
      std::vector<bool> tool_loaded;
      /// What check_initial_scene found worth a warning.
      std::vector<std::string> scene_warnings;
      unsigned int             refinement_rows = 0;
      /// The release (Springback/Enabled), once done; why it failed.
      std::unique_ptr<springback::ReleaseSummary> released;
      /// A plane-strain channel's angles and curl, before and after.
      std::unique_ptr<std::array<springback::ChannelMeasures, 2>> channel;
      std::vector<springback::PointSpringback>                    at_points;
      std::string springback_failure;
      double      springback_seconds = 0; // its wall time
      /// The trimmed part's cells (Trimming), what the trim did, why it
      /// failed, its wall time.
      std::unique_ptr<trimming::KeptCells>  kept;
      std::unique_ptr<trimming::TrimReport> trimmed;
      std::string                           trim_failure;
      double                                trim_seconds = 0;
      /// The sprung part's displacement on the state's DoFs (owned), once
      /// the release succeeded: what a next operation starts from.
      std::unique_ptr<VectorType> sprung_shape;
      /// The earlier run this one continues (Geometry/Start from).
      std::unique_ptr<EarlierRun> earlier;
      /// The split ring's opening (Springback/Slit).
      std::unique_ptr<springback::RingOpening> opening;
      /// The step solver's body forces are those of the current mesh's
      /// last converged step (false after a mesh change without a step).
      bool   forces_current = false;
      double last_dt        = 0; // s, of the last converged step
    };
  } // namespace simulation
} // namespace formsolve
