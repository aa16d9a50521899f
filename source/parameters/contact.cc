#include <formsolve/parameters/choice.h>
#include <formsolve/parameters/choices.h>
#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    namespace
    {
      const Choice<AdaptiveEstimate> estimate_names{
        {"force", AdaptiveEstimate::force},
        {"projection", AdaptiveEstimate::projection}};
      const Choice<FactorUpdate> factor_update_names{
        {"iteration", FactorUpdate::iteration},
        {"iteration and predictor", FactorUpdate::and_predictor},
        {"step", FactorUpdate::step}};
    } // namespace

    void Contact::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      declare_strategy(prm);
      declare_adaptive(prm);
      declare_passes(prm);
      prm.leave_subsection();
    }

    /// The strategy and the penetration it aims at or bounds.
    void Contact::declare_strategy(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Penalty strategy",
        "adaptive-strict",
        Selection(choices("Contact/Penalty strategy")),
        "How penalty factors are chosen. fixed: 'Penalty factor' (or the "
        "tool's own) times the nodal contact area. adaptive: per contact "
        "pair and Newton iteration from the current system, so that the "
        "penetration is about 'Allowed penetration' (doc/theory.md). "
        "adaptive-strict: adaptive, and a converged step with a penetration "
        "above the allowed one is solved again with those factors scaled up. "
        "augmented-lagrangian: Uzawa updates of a multiplier per pair on "
        "the factors of 'Augmented Lagrangian penalty', the step re-solved "
        "until no node is deeper than 'Allowed penetration'.");
      prm.declare_entry(
        "Augmented Lagrangian penalty",
        "fixed",
        Selection("fixed|adaptive"),
        "augmented-lagrangian: the factors the Uzawa updates run on, "
        "fixed ('Penalty factor') or adaptive (as strategy adaptive).");
      prm.declare_entry(
        "Penalty factor",
        "1e5",
        Double(),
        "Fixed penalty (N/mm^3): contact pressure per mm of "
        "penetration. Each node gets this times its contact area; the "
        "adaptive strategies start from it.");
      prm.declare_entry("Allowed penetration",
                        "1e-3",
                        Double(),
                        "delta (mm): penetration the adaptive strategies aim "
                        "at (adaptive) or bound (adaptive-strict).");
    }

    /// The estimate of the adaptive factors.
    void Contact::declare_adaptive(ParameterHandler &prm)
    {
      prm.declare_entry("Lower bound",
                        "1e-3",
                        Double(0),
                        "Adaptive: eps_k >= this * K_kk/dt, K_kk the tangent "
                        "diagonal of the node along the tool normal (-).");
      prm.declare_entry("Upper bound",
                        "1e4",
                        Double(0),
                        "Adaptive: eps_k <= this * K_kk/dt (-).");
      prm.declare_entry(
        "Adaptive estimate",
        "force",
        Selection(estimate_names.pattern()),
        "projection: eps_k = n.(r + K dv)_k / delta, the published method "
        "with the node moved to penetration delta (dv) through the tangent "
        "K; force: its limit dv -> 0, eps_k = n.r_k / delta, the normal "
        "force the node carries divided by delta. In the flow formulation "
        "the tangent of rigid zones is a cutoff viscosity, not a stiffness, "
        "and projection overestimates by orders of magnitude "
        "(doc/contact.md).");
      prm.declare_entry(
        "Target fraction",
        "0.9",
        Double(0.01, 1),
        "Adaptive estimates aim at this fraction of 'Allowed penetration' "
        "(-). Below 1, adaptive-strict needs fewer re-solves, since fewer "
        "nodes end a step deeper than allowed (measured with 0.9 against 1: "
        "4-6 % fewer Newton iterations for adaptive-strict, 0.4-1.6 % more "
        "for adaptive; doc/convergence.md).");
      prm.declare_entry(
        "Damping",
        "10",
        Double(1),
        "Adaptive: a factor may change by at most this ratio "
        "per estimate; the first estimate starts from the fixed "
        "penalty (-).");
      prm.declare_entry(
        "Freeze factors",
        "true",
        Bool(),
        "Adaptive: stop updating the factors in a step once the "
        "contact set is unchanged between two iterations (a pair locked "
        "by 'Max status flips' counts as unchanged while locked). No "
        "effect with 'Factor update = step'.");
      prm.declare_entry(
        "Factor update",
        "iteration",
        Selection(factor_update_names.pattern()),
        "Adaptive: when the factors are estimated. iteration: at every "
        "Newton iteration from the current system (until 'Freeze factors' "
        "stops them); at a step's predictor, where the body is far from "
        "equilibrium, the last factors are kept. iteration and predictor: "
        "at the predictor too. step: each "
        "Newton solve keeps the factors the last converged solve estimated "
        "(pairs without one start from 'Penalty factor'); the estimate runs "
        "at convergence, for the next solve, and at adaptive-strict's "
        "correction within a solve. Measured in doc/convergence.md.");
    }

    /// Passes over a step, friction and the search for pairs.
    void Contact::declare_passes(ParameterHandler &prm)
    {
      prm.declare_entry("Max status flips",
                        "4",
                        Integer(1),
                        "Contact status changes of one node-tool pair within "
                        "one Newton solve (each strict or Uzawa pass is a "
                        "solve) after which its status is locked for the rest "
                        "of the solve.");
      prm.declare_entry(
        "Max strict passes",
        "5",
        Integer(0),
        "adaptive-strict and augmented-lagrangian: re-solves of "
        "one step at most; a step still deeper than allowed "
        "after them is kept and reported in solver.csv (pairs_over_allowed).");
      prm.declare_entry(
        "Strict check residual",
        "0.1",
        Double(0, 1),
        "adaptive-strict: within each solve, once |r|/|f| falls below "
        "this with the contact set unchanged, the nodes deeper than "
        "allowed get their factors corrected there and the solve goes "
        "on; this counts as one of the Max strict passes and saves the "
        "re-solve after convergence (-). 0: check only after "
        "convergence.");
      prm.declare_entry("Friction regularisation velocity",
                        "1e-3",
                        Double(),
                        "v0 (mm/s) of the friction law f_t = -mu p (2/pi) "
                        "atan(|v_t|/v0) v_t/|v_t|.");
      prm.declare_entry(
        "Search distance",
        "1",
        Double(),
        "Sheet nodes farther than this from a tool (mm) are not "
        "checked for contact with it in the current step.");
    }

    void Contact::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      penalty_strategy    = prm.get("Penalty strategy");
      al_penalty          = prm.get("Augmented Lagrangian penalty");
      penalty_factor      = prm.get_double("Penalty factor");
      allowed_penetration = prm.get_double("Allowed penetration");
      lower_bound         = prm.get_double("Lower bound");
      upper_bound         = prm.get_double("Upper bound");
      freeze              = prm.get_bool("Freeze factors");
      factor_update       = factor_update_names.parse(prm.get("Factor update"));
      adaptive_estimate   = estimate_names.parse(prm.get("Adaptive estimate"));
      damping             = prm.get_double("Damping");
      target_fraction     = prm.get_double("Target fraction");
      max_status_flips    = prm.get_integer("Max status flips");
      max_strict_passes   = prm.get_integer("Max strict passes");
      strict_check_residual = prm.get_double("Strict check residual");
      regularisation_velocity =
        prm.get_double("Friction regularisation velocity");
      search_distance = prm.get_double("Search distance");
      prm.leave_subsection();
    }

    void Contact::validate() const
    {
      require_positive(penalty_factor, "Contact/Penalty factor", "N/mm^3");
      require_positive(allowed_penetration,
                       "Contact/Allowed penetration",
                       "mm");
      require(std::isfinite(upper_bound) && upper_bound > lower_bound,
              "Contact/Upper bound",
              "must exceed Contact/Lower bound");
      require_positive(regularisation_velocity,
                       "Contact/Friction regularisation velocity",
                       "mm/s");
      require_positive(search_distance, "Contact/Search distance", "mm");
    }
  } // namespace parameters
} // namespace formsolve
