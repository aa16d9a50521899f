// The pieces Newton's method is made of, each on its own toy
// (solver/line_search.h, solver/newton_steps.h; doc/theory.md sections 8, 9):
// the line search's acceptance, regula falsi, bracket halving and fallback to
// the longest descending trial on scalar potentials; the nonmonotone merit
// reference; Deuflhard's error estimate; the inexact linear tolerance; the
// Picard schedule; and what follows a stall.
#include <formsolve/newton/line_search.h>
#include <formsolve/newton/newton_steps.h>

#include "check.h"

#include <cmath>
#include <utility>
#include <vector>

using namespace formsolve;
using namespace formsolve::solver;

namespace
{
  /// A line search on the potential phi(alpha) with derivative g: the merit
  /// is |g| (as for a problem whose residual is the gradient). Records the
  /// trials.
  struct Toy
  {
    explicit Toy(std::function<double(double)> g)
        : g(std::move(g))
    {}

    std::function<double(double)> g;
    std::vector<double>           alphas;

    LineSearchResult run(const unsigned int max_steps, const double reference)
    {
      alphas.clear();
      return LineSearch(max_steps)
        .search(g(0), reference, [&](double a, unsigned int) {
          alphas.push_back(a);
          return LineSearchTrial{std::abs(g(a)), g(a)};
        });
    }
  };

  void line_search()
  {
    // A convex quadratic with its minimum beyond the full step: the full
    // step descends and is taken at once.
    Toy  far([](double a) { return 2 * (a - 3); });
    auto r = far.run(6, std::abs(far.g(0)));
    test::close("full step taken where it descends", r.alpha, 1, 0);
    test::close("one trial", far.alphas.size(), 1, 0);

    // Minimum at 0.3: g turns positive at the full step; regula falsi
    // lands on it (the secant of a linear g is exact).
    Toy near([](double a) { return 2 * (a - 0.3); });
    r = near.run(6, std::abs(near.g(0)));
    test::close("regula falsi: second trial at the root", r.alpha, 0.3, 1e-14);
    test::close("regula falsi: two trials", near.alphas.size(), 2, 0);

    // Regula falsi is kept at 0.1 of the upper end at least.
    Toy steep([](double a) { return a < 0.999 ? -1e-3 : 1e3; });
    r = steep.run(1, 1e9);
    test::close("regula falsi clamped to 0.1 a_hi",
                steep.alphas[1],
                0.1,
                1e-15);

    // g < 0 everywhere but the merit grows beyond 0.3: halving from 1,
    // then the bracket [0.25, 0.5] halved; when the trials run out the
    // longest descending trial is taken, though the last trial was elsewhere.
    Toy grows([](double a) { return a <= 0.3 ? -1. + a : -10. * a; });
    r                                  = grows.run(3, 0.95);
    const std::vector<double> expected = {1, 0.5, 0.25, 0.375};
    test::close("halving, then the bracket halved",
                grows.alphas == expected,
                1,
                0);
    test::close("the longest descending trial", r.alpha, 0.25, 0);
    test::close("taken without an evaluation there yet", r.evaluated, 0, 0);
    test::close("not stalled", r.stalled, 0, 0);

    Toy flat([](double a) { return a > 0.9 ? -1. : -20.; });
    r = flat.run(2, 0.5);
    test::close("no trial below the reference: stalled", r.stalled, 1, 0);
    test::close("stalled at the last trial", r.alpha, flat.alphas.back(), 0);

    Toy ascent([](double) { return 1.; });
    r = ascent.run(6, 10);
    test::close("not a descent direction: one trial, full step",
                ascent.alphas.size() == 1 && r.alpha == 1,
                1,
                0);
  }

  void pieces()
  {
    MeritHistory m(3, 5.);
    for (const double x : {4., 1., 2.})
      m.push(x);
    test::close("nonmonotone reference: largest of the last 3",
                m.reference(),
                4,
                0);
    m.push(0.5);
    test::close("nonmonotone reference: oldest dropped", m.reference(), 2, 0);
    m.reset(0.1);
    test::close("reset", m.reference(), 0.1, 0);

    ErrorEstimate e(parameters::CorrectionMeasure::contraction);
    test::close("first correction: itself", e.factor(1, 0, true), 1, 0);
    e.record(1., 0, true);
    test::close("contraction 1/4: error 1/3 of the step",
                e.factor(0.25, 0, true),
                1. / 3.,
                1e-15);
    test::close("contraction above 1/2: the step itself",
                e.factor(0.6, 0, true),
                1,
                0);
    test::close("not a full step: the step itself",
                e.factor(0.25, 0, false),
                1,
                0);
    e.forget();
    test::close("after new equations: the step itself",
                e.factor(0.25, 0, true),
                1,
                0);
    ErrorEstimate last(parameters::CorrectionMeasure::last);
    last.record(1, 0, true);
    test::close("Correction measure = last", last.factor(0.25, 0, true), 1, 0);

    parameters::NonlinearSolver p;
    p.forcing            = 0.3;
    p.residual_tolerance = 1e-5;
    test::close("forcing far from the tolerance: capped at 0.1",
                linear_tolerance(p, 1., false),
                0.1,
                0);
    test::close("forcing: 0.3 |r|/|f|",
                linear_tolerance(p, 1e-2, false),
                3e-3,
                1e-18);
    test::close("near the tolerance: 0.5 tol/(|r|/|f|)",
                linear_tolerance(p, 1e-4, false),
                0.05,
                1e-15);
    test::close("tight: the solver's own",
                linear_tolerance(p, 1e-2, true),
                0,
                0);

    p.picard_iterations = 2;
    PicardSchedule s(p);
    test::close("Picard first", s.picard() && !s.newton_next(1), 1, 0);
    s.advance(1, false);
    s.advance(2, false);
    test::close("then Newton", !s.picard() && s.newton_next(3), 1, 0);
    s.advance(3, true);
    unsigned int picard = 0;
    for (unsigned int it = 4; it < 10; ++it)
      {
        picard += s.picard();
        s.advance(it, false);
      }
    // The stall's own tangent is a secant one, then three more.
    test::close("a fallback: four direct directions", picard, 4, 0);

    StallPolicy exact(false, true);
    auto        r = exact.respond(true, true, true);
    test::close("exact solves, first stall: retry on the exact tangent",
                r.retry && !r.rejected && !r.fallback,
                1,
                0);
    r = exact.respond(true, true, true);
    test::close("second stall in a row: Picard fallback",
                r.fallback && !r.retry,
                1,
                0);
    StallPolicy inexact(true, true);
    r = inexact.respond(false, false, true);
    test::close("inexact direction that does not descend: rejected",
                r.rejected && inexact.tight(),
                1,
                0);
  }
} // namespace

int main()
{
  line_search();
  pieces();
  return test::result();
}
