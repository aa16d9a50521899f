// The line search of Newton's method (doc/theory.md, section 8) on the
// directional derivative g(alpha) = dx . r(x + alpha dx) of the potential,
// against a nonmonotone reference merit; and that reference. Separate from
// Newton so that each can be read and tested alone (tests/unit/line_search).
#pragma once

#include <deque>
#include <functional>

namespace formsolve
{
  namespace solver
  {
    /// The largest merit of the last @p memory iterates (Grippo, Lampariello
    /// and Lucidi): a trial is measured against it. Memory 1 is monotone.
    class MeritHistory
    {
    public:
      MeritHistory(const unsigned int memory, const double first);
      /// The merit of a new iterate.
      void push(const double merit);
      /// Forget the earlier iterates (the equations changed).
      void   reset(const double merit);
      double reference() const;

    private:
      unsigned int       memory;
      std::deque<double> merits;
    };

    /// What one trial of the search measured.
    struct LineSearchTrial
    {
      double merit = 0; // |(r, extra residual)| at the trial
      double slope = 0; // g(alpha)
    };

    struct LineSearchResult
    {
      double alpha = 1;
      /// No trial lowered the merit: alpha is that of the last trial.
      bool stalled = false;
      /// Whether the last trial evaluated was at alpha (else the caller
      /// evaluates there: the longest descending trial, taken when the
      /// trials ran out).
      bool evaluated = true;
    };

    class LineSearch
    {
    public:
      /// At most @p max_steps trials after the full step.
      explicit LineSearch(const unsigned int max_steps);

      /// Accepts a trial with a smaller merit than @p reference whose |g|
      /// has dropped to half |@p g0|, or the full step where it descends. A
      /// trial that still descends (g < 0, smaller merit) is too short: it
      /// becomes the lower end of a bracket, which is then halved. Above any
      /// such trial: regula falsi towards g = 0 where g turned positive,
      /// halving where g < 0 but the merit grew. When the trials run out,
      /// the longest descending trial is taken. @p trial(alpha, k) evaluates
      /// the k-th trial (k = 0: the full step, alpha = 1).
      LineSearchResult
      search(const double g0,
             const double reference,
             const std::function<LineSearchTrial(double, unsigned int)> &trial)
        const;

    private:
      unsigned int max_steps;
    };
  } // namespace solver
} // namespace formsolve
