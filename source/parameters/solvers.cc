#include <formsolve/parameters/choice.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/solvers.h>



namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    namespace
    {
      const Choice<EndOfRun> end_of_run_names{
        {"stroke", EndOfRun::stroke},
        {"holder release", EndOfRun::holder_release},
        {"draw-through", EndOfRun::draw_through}};
      const Choice<Tangent>           tangent_names{{"newton", Tangent::newton},
                                          {"stress-velocity",
                                                     Tangent::stress_velocity}};
      const Choice<CorrectionMeasure> correction_measure_names{
        {"contraction", CorrectionMeasure::contraction},
        {"last correction", CorrectionMeasure::last}};
      const Choice<Predictor> predictor_names{
        {"previous velocity", Predictor::previous_velocity},
        {"keep contact", Predictor::keep_contact}};
      const Choice<FirstStepStart> first_step_start_names{
        {"rest", FirstStepStart::rest},
        {"coarser mesh", FirstStepStart::coarser_mesh}};
    } // namespace

    void TimeStepping::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      prm.declare_entry(
        "Time step",
        "0.25",
        Double(),
        "Nominal (and largest) time step (s). With the punch speed it sets "
        "the punch travel per step.");
      prm.declare_entry(
        "Minimum time step",
        "1e-3",
        Double(),
        "Step control: a step that fails (Newton diverges or stalls, the "
        "linear solver fails) is retried with the time step multiplied by "
        "'Cutback factor'; below this time step (s) the run stops, after "
        "writing the output of the last converged step.");
      prm.declare_entry("Cutback factor",
                        "0.5",
                        Double(0.01, 0.9),
                        "Factor on the time step after a failed step (-).");
      prm.declare_entry(
        "Growth factor",
        "1.5",
        Double(1, 10),
        "After an easy step (at most 'Easy step iterations' Newton "
        "iterations) the time step grows by this factor, up to 'Time "
        "step' (-).");
      prm.declare_entry("Easy step iterations",
                        "8",
                        Integer(1),
                        "Newton iterations (all passes of a step) up to "
                        "which a step counts as easy.");
      prm.declare_entry(
        "Regrowth after steps",
        "4",
        Integer(0),
        "Below 'Time step', the time step also grows by 'Growth factor' "
        "after this many converged steps in a row without a cut and without "
        "growth, easy or not (steps). Where every step needs more than "
        "'Easy step iterations' (fine meshes), a single cut would otherwise "
        "halve the time step for the rest of the run. 0: growth after easy "
        "steps only.");
      prm.declare_entry("Max cutbacks",
                        "8",
                        Integer(0),
                        "Retries of one step at most; then the run stops.");
      prm.declare_entry(
        "End of run",
        "stroke",
        Selection(end_of_run_names.pattern()),
        "stroke: the run ends at the punch stroke. holder release: also "
        "ends once the blank rim has left the blank holder. draw-through: "
        "also ends once the whole blank lies inside the die opening (the "
        "cup is drawn through). The reason is printed and written to "
        "run-summary.txt.");
      prm.leave_subsection();
    }

    void TimeStepping::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      time_step         = prm.get_double("Time step");
      minimum_time_step = prm.get_double("Minimum time step");
      cutback_factor    = prm.get_double("Cutback factor");
      growth_factor     = prm.get_double("Growth factor");
      easy_iterations   = prm.get_integer("Easy step iterations");
      regrowth_steps    = prm.get_integer("Regrowth after steps");
      max_cutbacks      = prm.get_integer("Max cutbacks");
      end_of_run        = end_of_run_names.parse(prm.get("End of run"));
      prm.leave_subsection();
    }

    void TimeStepping::validate() const
    {
      require_positive(time_step, "Time stepping/Time step", "s");
      require_positive(minimum_time_step,
                       "Time stepping/Minimum time step",
                       "s");
      require(minimum_time_step <= time_step,
              "Time stepping/Minimum time step",
              "must not exceed Time stepping/Time step");
    }

    void NonlinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      declare_convergence(prm);
      declare_iterations(prm);
      declare_first_step(prm);
      prm.leave_subsection();
    }

    /// The tangent and when a solve has converged.
    void NonlinearSolver::declare_convergence(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Tangent",
        "stress-velocity",
        Selection(tangent_names.pattern()),
        "Linearisation of the flow law. newton: the derivative of the "
        "stress as a function of the velocity; for a nearly rate-insensitive "
        "law it keeps almost no stiffness along the current strain rate and "
        "overshoots. stress-velocity: the stress direction is linearised as "
        "an unknown of its own at each quadrature point and eliminated "
        "(doc/theory.md, eq. 4b): the same converged solution in fewer "
        "iterations.");
      prm.declare_entry("Max iterations",
                        "60",
                        Integer(1),
                        "Newton iterations per solve before the step fails "
                        "(and is retried with a smaller time step).");
      prm.declare_entry(
        "Residual tolerance",
        "1e-5",
        Double(0),
        "Converged when |r| <= tol * |f_int|, the norm of the element "
        "internal-force vectors, and the blank-holder force is within tol "
        "of its set value (-) ... On the default cup, 1e-5 moves forces, "
        "thickness and penetration by at most 3e-5 of their values from "
        "those at 1e-8 (doc/convergence.md).");
      prm.declare_entry("Correction tolerance",
                        "1e-5",
                        Double(0),
                        "... and the velocity error left, by Correction "
                        "measure, is <= tol * |v| (-), and the contact set is "
                        "unchanged.");
      prm.declare_entry(
        "Correction measure",
        "contraction",
        Selection(correction_measure_names.pattern()),
        "The velocity error compared with Correction tolerance. last "
        "correction: |dv| of the iteration just taken, which bounds the "
        "error before it. contraction: the error it leaves, theta/(1 - "
        "theta) |dv| with theta = |dv_k|/|dv_k-1| the contraction of two "
        "full Newton steps in a row that did not change the contact set, "
        "where theta <= 1/2 (Deuflhard's estimate; |dv| elsewhere). It saves "
        "the last iteration of a quadratically converging solve.");
      prm.declare_entry(
        "Forcing",
        "0",
        Double(0, 1),
        "Inexact Newton: a linear solve that iterates (GMRES with reused, "
        "single-precision, low-rank or symmetric-part factors) stops at "
        "|b - A x|/|b| <= min(0.1, max(Forcing * |r|/|f|, 0.5 Residual "
        "tolerance/(|r|/|f|))), with |r|/|f| the Newton residual of the "
        "iterate (the second term: near convergence no more accuracy than the "
        "next residual needs), and never below Linear solver/Reuse tolerance "
        "(-). "
        "0: always to Reuse tolerance. A solve with fresh exact factors is "
        "exact whatever this is.");
    }

    /// How an iteration starts and moves: predictor, line search, deferred
    /// tangent, Picard.
    void NonlinearSolver::declare_iterations(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Predictor",
        "keep contact",
        Selection(predictor_names.pattern()),
        "The first iterate of a step. previous velocity: the previous step's "
        "velocity. keep contact: the same, except at the nodes that were in "
        "contact at the end of the previous step and that this velocity "
        "would lift off their tool (sliding over a tool radius, or under a "
        "moving holder): their normal velocity is corrected so that they "
        "just touch the tool at the end of the step (predicted gap 0, zero "
        "force), so that the first Newton direction keeps them on it "
        "(doc/theory.md section 8).");
      prm.declare_entry(
        "Max line search steps",
        "6",
        Integer(0, 30),
        "Trial step lengths per Newton iteration after the full step: "
        "regula falsi on the directional derivative dv.r(v + alpha dv) of "
        "the potential, then halving of the bracket (doc/theory.md section "
        "8).");
      prm.declare_entry(
        "Deferred tangent",
        "true",
        Bool(),
        "Where a Newton step is expected to be the last (quadratic "
        "convergence predicts |r|/|f| <= Residual tolerance after it, and "
        "the step itself meets Correction tolerance), assemble the residual "
        "of its iterate first and the tangent only if the iteration goes on "
        "(or an adaptive penalty estimate reads it). A wrong guess costs one "
        "residual assembly; the iterates are the same (doc/theory.md "
        "section 8).");
      prm.declare_entry(
        "Line search memory",
        "3",
        Integer(1, 20),
        "Nonmonotone line search: a trial is measured against the largest "
        "merit (|r| with the holder's force residual, N) of this many "
        "previous iterates, the current one included (Grippo, Lampariello "
        "and Lucidi). 1 is the monotone search: the merit must fall at "
        "every iteration. Larger values let Newton cross a rise of |r| "
        "while a plastic zone forms (doc/theory.md section 8).");
      prm.declare_entry(
        "Picard iterations",
        "0",
        Integer(0),
        "Direct (secant) iterations at the start of every step.");
      prm.declare_entry(
        "Picard fallback",
        "true",
        Bool(),
        "When the line search fails twice in a row (the second time along "
        "the exact tangent's direction, doc/theory.md section 8), do three "
        "direct (secant) iterations, then return to Newton.");
      prm.declare_entry(
        "Log iterations",
        "false",
        Bool(),
        "Print one line per nonlinear iteration: residual, "
        "correction, line-search factor, contact-set changes with the "
        "pairs each tool closed (+) and opened (-).");
    }

    /// Where the first step's Newton starts.
    void NonlinearSolver::declare_first_step(ParameterHandler &prm)
    {
      prm.declare_entry(
        "First step start",
        "coarser mesh",
        Selection(first_step_start_names.pattern()),
        "Where Newton starts in the first step, when the sheet is at rest. "
        "rest: zero velocity. coarser mesh: the first step is solved first "
        "on the mesh one level coarser everywhere (in the plane and through "
        "the thickness), and its velocity, holder velocity and contact "
        "state, interpolated onto the mesh of the run, start the step there. "
        "The first step from rest needs more Newton iterations the finer the "
        "mesh; from the coarser solution it needs 5-9 (doc/convergence.md, "
        "\"The first step from a coarser mesh\"). Used only where the "
        "coarser mesh keeps the bending: see Coarse cell size limit; "
        "otherwise, and when the coarse solve fails, the step starts from "
        "rest.");
      prm.declare_entry(
        "Coarse cell size limit",
        "2",
        Double(0),
        "First step start = coarser mesh is used only when the cells of the "
        "coarser mesh are on average no longer than this many initial sheet "
        "thicknesses in the plane (sheet thicknesses, -). On coarser meshes "
        "the coarse solution bends the sheet over the punch nose too "
        "differently to be a good start (measured: 1.5 thicknesses helps, "
        "3 hurts).");
    }

    void NonlinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      tangent              = tangent_names.parse(prm.get("Tangent"));
      max_iterations       = prm.get_integer("Max iterations");
      residual_tolerance   = prm.get_double("Residual tolerance");
      correction_tolerance = prm.get_double("Correction tolerance");
      forcing              = prm.get_double("Forcing");
      correction_measure =
        correction_measure_names.parse(prm.get("Correction measure"));
      predictor             = predictor_names.parse(prm.get("Predictor"));
      max_line_search_steps = prm.get_integer("Max line search steps");
      line_search_memory    = prm.get_integer("Line search memory");
      deferred_tangent      = prm.get_bool("Deferred tangent");
      picard_iterations     = prm.get_integer("Picard iterations");
      picard_fallback       = prm.get_bool("Picard fallback");
      log_iterations        = prm.get_bool("Log iterations");
      first_step_start =
        first_step_start_names.parse(prm.get("First step start"));
      coarse_cell_size_limit = prm.get_double("Coarse cell size limit");
      prm.leave_subsection();
    }

    void NonlinearSolver::validate() const
    {
      require_positive(residual_tolerance,
                       "Nonlinear solver/Residual tolerance",
                       "");
      require_positive(correction_tolerance,
                       "Nonlinear solver/Correction tolerance",
                       "");
    }

  } // namespace parameters
} // namespace formsolve
