#include <formsolve/parameters/choices.h>
#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
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

    void Contact::declare(Declarations &d)
    {
      const Subsection s(d, "Contact");
      declare_strategy(d);
      declare_adaptive(d);
      declare_passes(d);
    }

    /// The strategy and the penetration it aims at or bounds.
    void Contact::declare_strategy(Declarations &d)
    {
      d.add(
        "Penalty strategy",
        penalty_strategy,
        one_of(choices("Contact/Penalty strategy")),
        "How penalty factors are chosen. fixed: 'Penalty factor' (or the "
        "tool's own) times the nodal contact area. adaptive: per contact "
        "pair and Newton iteration from the current system, so that the "
        "penetration is about 'Allowed penetration' (doc/theory.md). "
        "adaptive-strict: adaptive, and a converged step with a penetration "
        "above the allowed one is solved again with those factors scaled up. "
        "augmented-lagrangian: Uzawa updates of a multiplier per pair on "
        "the factors of 'Augmented Lagrangian penalty', the step re-solved "
        "until no node is deeper than 'Allowed penetration'.");
      d.add("Augmented Lagrangian penalty",
            al_penalty,
            one_of("fixed|adaptive"),
            "augmented-lagrangian: the factors the Uzawa updates run on, "
            "fixed ('Penalty factor') or adaptive (as strategy adaptive).");
      d.add("Penalty factor",
            penalty_factor,
            number("N/mm^3"),
            "Fixed penalty (N/mm^3): contact pressure per mm of "
            "penetration. Each node gets this times its contact area; the "
            "adaptive strategies start from it.");
      d.add("Allowed penetration",
            allowed_penetration,
            number("mm"),
            "delta (mm): penetration the adaptive strategies aim "
            "at (adaptive) or bound (adaptive-strict).");
    }

    /// The estimate of the adaptive factors.
    void Contact::declare_adaptive(Declarations &d)
    {
      d.add("Lower bound",
            lower_bound,
            number("-", 0),
            "Adaptive: eps_k >= this * K_kk/dt, K_kk the tangent "
            "diagonal of the node along the tool normal (-).");
      d.add("Upper bound",
            upper_bound,
            number("-", 0),
            "Adaptive: eps_k <= this * K_kk/dt (-).");
      d.add(
        "Adaptive estimate",
        adaptive_estimate,
        estimate_names,
        "projection: eps_k = n.(r + K dv)_k / delta, the published method "
        "with the node moved to penetration delta (dv) through the tangent "
        "K; force: its limit dv -> 0, eps_k = n.r_k / delta, the normal "
        "force the node carries divided by delta. In the flow formulation "
        "the tangent of rigid zones is a cutoff viscosity, not a stiffness, "
        "and projection overestimates by orders of magnitude "
        "(doc/contact.md).");
      d.add(
        "Target fraction",
        target_fraction,
        number("-", 0.01, 1),
        "Adaptive estimates aim at this fraction of 'Allowed penetration' "
        "(-). Below 1, adaptive-strict needs fewer re-solves, since fewer "
        "nodes end a step deeper than allowed (measured with 0.9 against 1: "
        "4-6 % fewer Newton iterations for adaptive-strict, 0.4-1.6 % more "
        "for adaptive; doc/convergence.md).");
      d.add("Damping",
            damping,
            number("-", 1),
            "Adaptive: a factor may change by at most this ratio "
            "per estimate; the first estimate starts from the fixed "
            "penalty (-).");
      d.add("Freeze factors",
            freeze,
            "Adaptive: stop updating the factors in a step once the "
            "contact set is unchanged between two iterations (a pair locked "
            "by 'Max status flips' counts as unchanged while locked). No "
            "effect with 'Factor update = step'.");
      d.add(
        "Factor update",
        factor_update,
        factor_update_names,
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
    void Contact::declare_passes(Declarations &d)
    {
      d.add("Max status flips",
            max_status_flips,
            whole_number(1),
            "Contact status changes of one node-tool pair within "
            "one Newton solve (each strict or Uzawa pass is a "
            "solve) after which its status is locked for the rest "
            "of the solve.");
      d.add(
        "Max strict passes",
        max_strict_passes,
        whole_number(0),
        "adaptive-strict and augmented-lagrangian: re-solves of "
        "one step at most; a step still deeper than allowed "
        "after them is kept and reported in solver.csv (pairs_over_allowed).");
      d.add("Strict check residual",
            strict_check_residual,
            number("-", 0, 1),
            "adaptive-strict: within each solve, once |r|/|f| falls below "
            "this with the contact set unchanged, the nodes deeper than "
            "allowed get their factors corrected there and the solve goes "
            "on; this counts as one of the Max strict passes and saves the "
            "re-solve after convergence (-). 0: check only after "
            "convergence.");
      d.add("Friction regularisation velocity",
            regularisation_velocity,
            number("mm/s"),
            "v0 (mm/s) of the friction law f_t = -mu p (2/pi) "
            "atan(|v_t|/v0) v_t/|v_t|.");
      d.add("Search distance",
            search_distance,
            number("mm"),
            "Sheet nodes farther than this from a tool (mm) are not "
            "checked for contact with it in the current step.");
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
