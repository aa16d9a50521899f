// The pieces of Newton's method besides the line search, each small enough
// to read and test alone (doc/theory.md, sections 8 and 9): the error a
// correction leaves, the inexact linear tolerance, the Picard schedule and
// what to do after a line search that found no acceptable trial.
#pragma once

#include <formsolve/parameters/solvers.h>

namespace formsolve
{
  namespace solver
  {
    /// The error a correction leaves (doc/theory.md, eq. 10a): where it and
    /// the last one are full steps that contract by theta <= 1/2 (Deuflhard),
    /// at most theta/(1 - theta) of it; else the correction itself.
    class ErrorEstimate
    {
    public:
      explicit ErrorEstimate(const parameters::CorrectionMeasure measure);

      /// The factor on a correction of @p step (main unknowns, absolute) and
      /// @p extra_step (extra ones, relative); @p full: a full step with the
      /// active set unchanged.
      double
      factor(const double step, const double extra_step, const bool full) const;
      /// The correction just taken.
      void record(const double step, const double extra_step, const bool full);
      /// The equations changed: the next correction contracts nothing.
      void forget() { last_full = false; }
      /// Whether the last correction was a full step.
      bool full() const { return last_full; }

    private:
      parameters::CorrectionMeasure measure;
      bool                          last_full = false;
      double                        last_step = 0, last_extra = 0;
    };

    /// Inexact Newton (doc/theory.md, section 9): the relative residual the
    /// next linear solve may stop at, min(0.1, max(forcing |r|/|f|,
    /// 0.5 tol/(|r|/|f|))) (Kelley's safeguard), or 0 (the solver's own) when
    /// @p tight.
    double linear_tolerance(const parameters::NonlinearSolver &p,
                            const double relative_residual,
                            const bool   tight);

    /// Direct (Picard) iterations: the first Picard iterations of a solve,
    /// and three after a stall (Picard fallback).
    class PicardSchedule
    {
    public:
      explicit PicardSchedule(const parameters::NonlinearSolver &p);
      /// Whether the current iteration's direction is a Picard one.
      bool picard() const { return now; }
      /// Whether the tangent of iteration @p it's trials is Newton's.
      bool newton_next(const unsigned int it) const;
      /// After iteration @p it: a stall (@p fall_back) starts the fallback.
      void advance(const unsigned int it, const bool fall_back);

    private:
      unsigned int initial;
      unsigned int left = 0; // fallback iterations left
      bool         now;
    };

    /// What follows a line search: the decisions of doc/theory.md section
    /// 8 after a stall (no trial lowered the merit) or a direction that
    /// does not descend.
    struct StallResponse
    {
      /// An inexact direction that does not descend, or along which no
      /// trial lowered the merit, is not taken: stay and solve again to the
      /// linear solver's own tolerance.
      bool rejected = false;
      /// Stay and take the next direction from the exact tangent.
      bool retry = false;
      /// A few direct iterations from the last trial.
      bool fallback = false;
    };

    class StallPolicy
    {
    public:
      /// @p inexact: the linear solves may stop early (Forcing > 0).
      StallPolicy(const bool inexact, const bool picard_fallback);

      StallResponse
      respond(const bool stalled, const bool descends, const bool newton_next);
      /// Whether linear solves go to the solver's own tolerance: always
      /// without forcing, and once an inexact direction has failed.
      bool tight() const { return tight_solves; }

    private:
      bool tight_solves, picard_fallback, last_stalled = false;
    };
  } // namespace solver
} // namespace formsolve
