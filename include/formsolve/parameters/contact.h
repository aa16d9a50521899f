// Subsection "Contact": penalty strategy, friction law, contact search.
#pragma once

#include <string>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class AdaptiveEstimate
    {
      force,     // eps_k = n.r_b / delta
      projection // eps_k = n.(r_b + K_b dv) / delta, the published form
    };

    enum class FactorUpdate
    {
      iteration,     // at every Newton iteration; the predictor keeps the last
      and_predictor, // at every Newton iteration and at the step's predictor
      step           // held within a Newton solve, estimated at convergence
    };

    struct Contact
    {
      /// A name registered in contact/penalty_strategy.h; parsed once, into
      /// the strategy object, by contact::create_penalty_strategy.
      std::string      penalty_strategy        = "adaptive-strict";
      std::string      al_penalty              = "fixed"; // factors under Uzawa
      double           penalty_factor          = 1e5;     // N/mm^3
      double           allowed_penetration     = 1e-3;    // delta (mm)
      double           lower_bound             = 1e-3;    // eps_k dt / K_kk
      double           upper_bound             = 1e4;
      bool             freeze                  = true;
      FactorUpdate     factor_update           = FactorUpdate::iteration;
      AdaptiveEstimate adaptive_estimate       = AdaptiveEstimate::force;
      double           damping                 = 10;
      double           target_fraction         = 0.9;
      unsigned int     max_status_flips        = 4;
      unsigned int     max_strict_passes       = 5;
      double           strict_check_residual   = 0.1;  // |r|/|f|; 0: off
      double           regularisation_velocity = 1e-3; // mm/s
      double           search_distance         = 1;    // mm

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;

    private:
      void declare_strategy(Declarations &d);
      void declare_adaptive(Declarations &d);
      void declare_passes(Declarations &d);
    };
  } // namespace parameters
} // namespace formsolve
