// Stress-velocity (primal-dual) linearisation of the plastic flow law, after
// Chan, Golub and Mulet's Newton method for total variation: the direction of
// the deviatoric stress is an unknown of its own at each quadrature point,
// linearised together with the velocity and eliminated locally. For a nearly
// rate-insensitive law the plain Newton tangent keeps almost no stiffness
// along the current strain-rate direction (2 mu P_dev - (4/9) s/rate^3 D'(x)D'
// is singular there for m = 0) and overshoots; with the dual direction w in
// place of one D' the tangent stays positive while w differs from D'/rate, and
// is Newton's at convergence (doc/theory.md, eq. 4b).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/mandel.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    class DualStress
    {
    public:
      using Tensor = dealii::SymmetricTensor<2, 3>;

      /// Storage for @p n_cells cells (active cell index) with @p n_points
      /// quadrature points each; every point starts without a linearisation.
      /// With @p keep_metrics also each point's metric (a non-quadratic
      /// law's local compliance, where its next local solve starts).
      void reinit(const unsigned int n_cells,
                  const unsigned int n_points,
                  const bool         keep_metrics = false);

      /// Forget the last linearisation point (a rejected step, a new mesh):
      /// the next tangent is the secant one. The metrics stay: a start of
      /// the local solves, not a linearisation point.
      void reset();

      /// The dual direction w (scaled like D'/rate, |w| <= 1 in the norm
      /// sqrt(2/3 w:w)) at strain-rate deviator @p e of a trial iterate,
      /// from the linearisation at the accepted iterate; kept as the trial
      /// value of the point. @p cutoff: the rate below which the law is
      /// linear (rigid zone); @p smooth: the smooth law of Material/Rigid
      /// zone, where w = D'/sqrt(rate^2 + cutoff^2) everywhere.
      Tensor trial(const unsigned int cell,
                   const unsigned int q,
                   const Tensor      &e,
                   const double       cutoff,
                   const bool         smooth);

      /// The metric at the accepted iterate (or the last one before a
      /// reset()), where a non-quadratic law's local solve starts; nullptr
      /// if none is kept.
      const material::Mandel6x6 *start(const unsigned int cell,
                                       const unsigned int q) const
      {
        if (metrics.empty())
          return nullptr;
        const MetricState &p = metrics[cell * points + q];
        return p.valid ? &p.metric : nullptr;
      }
      /// Keep @p metric as the trial value of the point (if metrics are
      /// kept).
      void trial_metric(const unsigned int         cell,
                        const unsigned int         q,
                        const material::Mandel6x6 &metric)
      {
        if (!trial_metrics.empty())
          trial_metrics[cell * points + q] = MetricState{metric, true};
      }

      /// The last trial values become the linearisation point. A swap, not
      /// a copy: every assembly writes the trials of all points it visits,
      /// and revert() needs the previous point.
      void accept()
      {
        accepted.swap(trials);
        metrics.swap(trial_metrics);
      }

      /// Undo the last accept() (before any trial() since): the previous
      /// linearisation point again, the trials as they were. For a tangent
      /// assembled after its iterate was accepted (a deferred tangent).
      void revert()
      {
        accepted.swap(trials);
        metrics.swap(trial_metrics);
      }

      /// For the iteration log, before accept(): the points whose trial
      /// strain rate is at most @p cutoff (rigid), and how many points
      /// became rigid and plastic since the accepted iterate ({rigid, to
      /// rigid, to plastic}; no changes at a step's first iterate). This
      /// rank's points only.
      std::array<unsigned int, 3> rigid_transitions(const double cutoff) const;
      /// Forget the trials (a line search that is abandoned) and set every
      /// dual direction to its value at the accepted strain rate, e/rate
      /// (e/@p cutoff in rigid zones): the next tangent linearises about the
      /// accepted iterate itself.
      void restart(const double cutoff, const bool smooth);

    private:
      struct PointState
      {
        Tensor w;             // dual direction
        Tensor e;             // strain-rate deviator (1/s)
        bool   valid = false; // false: no linearisation point yet
      };
      struct MetricState
      {
        material::Mandel6x6 metric;
        bool                valid = false;
      };
      unsigned int             points = 0;
      std::vector<PointState>  accepted, trials;
      std::vector<MetricState> metrics, trial_metrics; // accepted, trials
    };
  } // namespace solver
} // namespace formsolve
