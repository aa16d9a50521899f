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
      void reinit(const unsigned int n_cells, const unsigned int n_points);

      /// Forget the last linearisation point (a rejected step, a new mesh):
      /// the next tangent is the secant one.
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

      /// The strain-rate deviator at the accepted iterate, where a
      /// non-quadratic law's local solve starts; nullptr if none.
      const Tensor *start(const unsigned int cell, const unsigned int q) const
      {
        const PointState &p = accepted[cell * points + q];
        return p.valid ? &p.e : nullptr;
      }

      /// The last trial values become the linearisation point. A swap, not
      /// a copy: every assembly writes the trials of all points it visits,
      /// and revert() needs the previous point.
      void accept() { accepted.swap(trials); }

      /// Undo the last accept() (before any trial() since): the previous
      /// linearisation point again, the trials as they were. For a tangent
      /// assembled after its iterate was accepted (a deferred tangent).
      void revert() { accepted.swap(trials); }

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
      unsigned int            points = 0;
      std::vector<PointState> accepted, trials;
    };
  } // namespace solver
} // namespace formsolve
