#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/solvers.h>



namespace formsolve
{
  namespace parameters
  {
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

    void TimeStepping::declare(Declarations &d)
    {
      const Subsection s(d, "Time stepping");
      d.add("Time step",
            time_step,
            number("s"),
            "Nominal (and largest) time step (s). With the punch speed it sets "
            "the punch travel per step.");
      d.add("Minimum time step",
            minimum_time_step,
            number("s"),
            "Step control: a step that fails (Newton diverges or stalls, the "
            "linear solver fails) is retried with the time step multiplied by "
            "'Cutback factor'; below this time step (s) the run stops, after "
            "writing the output of the last converged step.");
      d.add("Cutback factor",
            cutback_factor,
            number("-", 0.01, 0.9),
            "Factor on the time step after a failed step (-).");
      d.add("Growth factor",
            growth_factor,
            number("-", 1, 10),
            "After an easy step (at most 'Easy step iterations' Newton "
            "iterations) the time step grows by this factor, up to 'Time "
            "step' (-).");
      d.add("Easy step iterations",
            easy_iterations,
            whole_number(1),
            "Newton iterations (all passes of a step) up to "
            "which a step counts as easy.");
      d.add(
        "Regrowth after steps",
        regrowth_steps,
        whole_number(0),
        "Below 'Time step', the time step also grows by 'Growth factor' "
        "after this many converged steps in a row without a cut and without "
        "growth, easy or not (steps). Where every step needs more than "
        "'Easy step iterations' (fine meshes), a single cut would otherwise "
        "halve the time step for the rest of the run. 0: growth after easy "
        "steps only.");
      d.add("Max cutbacks",
            max_cutbacks,
            whole_number(0),
            "Retries of one step at most; then the run stops.");
      d.add("End of run",
            end_of_run,
            end_of_run_names,
            "stroke: the run ends at the punch stroke. holder release: also "
            "ends once the blank rim has left the blank holder. draw-through: "
            "also ends once the whole blank lies inside the die opening (the "
            "cup is drawn through). The reason is printed and written to "
            "run-summary.txt.");
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

    void NonlinearSolver::declare(Declarations &d)
    {
      const Subsection s(d, "Nonlinear solver");
      declare_convergence(d);
      declare_iterations(d);
      declare_first_step(d);
    }

    /// The tangent and when a solve has converged.
    void NonlinearSolver::declare_convergence(Declarations &d)
    {
      d.add(
        "Tangent",
        tangent,
        tangent_names,
        "Linearisation of the flow law. newton: the derivative of the "
        "stress as a function of the velocity; for a nearly rate-insensitive "
        "law it keeps almost no stiffness along the current strain rate and "
        "overshoots. stress-velocity: the stress direction is linearised as "
        "an unknown of its own at each quadrature point and eliminated "
        "(doc/theory.md, eq. 4b): the same converged solution in fewer "
        "iterations.");
      d.add("Max iterations",
            max_iterations,
            whole_number(1),
            "Newton iterations per solve before the step fails "
            "(and is retried with a smaller time step).");
      d.add("Residual tolerance",
            residual_tolerance,
            number("-", 0),
            "Converged when |r| <= tol * |f_int|, the norm of the element "
            "internal-force vectors, and the blank-holder force is within tol "
            "of its set value (-) ... On the default cup, 1e-5 moves forces, "
            "thickness and penetration by at most 3e-5 of their values from "
            "those at 1e-8 (doc/convergence.md).");
      d.add("Correction tolerance",
            correction_tolerance,
            number("-", 0),
            "... and the velocity error left, by Correction "
            "measure, is <= tol * |v| (-), and the contact set is "
            "unchanged.");
      d.add(
        "Correction measure",
        correction_measure,
        correction_measure_names,
        "The velocity error compared with Correction tolerance. last "
        "correction: |dv| of the iteration just taken, which bounds the "
        "error before it. contraction: the error it leaves, theta/(1 - "
        "theta) |dv| with theta = |dv_k|/|dv_k-1| the contraction of two "
        "full Newton steps in a row that did not change the contact set, "
        "where theta <= 1/2 (Deuflhard's estimate; |dv| elsewhere). It saves "
        "the last iteration of a quadratically converging solve.");
      d.add(
        "Forcing",
        forcing,
        number("-", 0, 1),
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
    void NonlinearSolver::declare_iterations(Declarations &d)
    {
      d.add(
        "Predictor",
        predictor,
        predictor_names,
        "The first iterate of a step. previous velocity: the previous step's "
        "velocity. keep contact: the same, except at the nodes that were in "
        "contact at the end of the previous step and that this velocity "
        "would lift off their tool (sliding over a tool radius, or under a "
        "moving holder): their normal velocity is corrected so that they "
        "just touch the tool at the end of the step (predicted gap 0, zero "
        "force), so that the first Newton direction keeps them on it "
        "(doc/theory.md section 8).");
      d.add("Max line search steps",
            max_line_search_steps,
            whole_number(0, 30),
            "Trial step lengths per Newton iteration after the full step: "
            "regula falsi on the directional derivative dv.r(v + alpha dv) of "
            "the potential, then halving of the bracket (doc/theory.md section "
            "8).");
      d.add(
        "Deferred tangent",
        deferred_tangent,
        "Where a Newton step is expected to be the last (quadratic "
        "convergence predicts |r|/|f| <= Residual tolerance after it, and "
        "the step itself meets Correction tolerance), assemble the residual "
        "of its iterate first and the tangent only if the iteration goes on "
        "(or an adaptive penalty estimate reads it). A wrong guess costs one "
        "residual assembly; the iterates are the same (doc/theory.md "
        "section 8).");
      d.add("Line search memory",
            line_search_memory,
            whole_number(1, 20),
            "Nonmonotone line search: a trial is measured against the largest "
            "merit (|r| with the holder's force residual, N) of this many "
            "previous iterates, the current one included (Grippo, Lampariello "
            "and Lucidi). 1 is the monotone search: the merit must fall at "
            "every iteration. Larger values let Newton cross a rise of |r| "
            "while a plastic zone forms (doc/theory.md section 8).");
      d.add("Picard iterations",
            picard_iterations,
            whole_number(0),
            "Direct (secant) iterations at the start of every step.");
      d.add("Picard fallback",
            picard_fallback,
            "When the line search fails twice in a row (the second time along "
            "the exact tangent's direction, doc/theory.md section 8), do three "
            "direct (secant) iterations, then return to Newton.");
      d.add("Log iterations",
            log_iterations,
            "Print one line per nonlinear iteration: residual, "
            "correction, line-search factor, contact-set changes with the "
            "pairs each tool closed (+) and opened (-).");
    }

    /// Where the first step's Newton starts.
    void NonlinearSolver::declare_first_step(Declarations &d)
    {
      d.add(
        "First step start",
        first_step_start,
        first_step_start_names,
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
      d.add(
        "Coarse cell size limit",
        coarse_cell_size_limit,
        number("", 0),
        "First step start = coarser mesh is used only when the cells of the "
        "coarser mesh are on average no longer than this many initial sheet "
        "thicknesses in the plane (sheet thicknesses, -). On coarser meshes "
        "the coarse solution bends the sheet over the punch nose too "
        "differently to be a good start (measured: 1.5 thicknesses helps, "
        "3 hurts).");
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
