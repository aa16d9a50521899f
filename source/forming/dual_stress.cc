#include <deal.II/base/exceptions.h>

#include <formsolve/forming/dual_stress.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace solver
  {
    void DualStress::reinit(const unsigned int n_cells,
                            const unsigned int n_points,
                            const bool         keep_metrics)
    {
      points = n_points;
      accepted.assign(n_cells * n_points, PointState());
      trials = accepted;
      metrics.assign(keep_metrics ? n_cells * n_points : 0, MetricState());
      trial_metrics = metrics;
    }

    void DualStress::reset()
    {
      for (auto &p : accepted)
        p.valid = false;
      trials        = accepted;
      trial_metrics = metrics;
    }

    void DualStress::restart(const double cutoff, const bool smooth)
    {
      for (auto &p : accepted)
        if (p.valid)
          {
            const double rate = std::sqrt(2. / 3. * (p.e * p.e));
            p.w               = p.e /
                  (smooth ? std::hypot(rate, cutoff) : std::max(rate, cutoff));
          }
      trials        = accepted;
      trial_metrics = metrics;
    }

    std::array<unsigned int, 3>
    DualStress::rigid_transitions(const double cutoff) const
    {
      const auto rigid = [cutoff](const PointState &p) {
        return std::sqrt(2. / 3. * (p.e * p.e)) <= cutoff;
      };
      std::array<unsigned int, 3> counts{{0, 0, 0}};
      for (std::size_t i = 0; i < trials.size(); ++i)
        if (trials[i].valid)
          {
            const bool now = rigid(trials[i]);
            counts[0] += now;
            // No accepted state (a step's first iterate): nothing to compare.
            if (accepted[i].valid)
              {
                const bool before = rigid(accepted[i]);
                counts[1] += now && !before;
                counts[2] += !now && before;
              }
          }
      return counts;
    }

    DualStress::Tensor DualStress::trial(const unsigned int cell,
                                         const unsigned int q,
                                         const Tensor      &e,
                                         const double       cutoff,
                                         const bool         smooth)
    {
      AssertIndexRange(cell * points + q, accepted.size());
      const PointState &base = accepted[cell * points + q];
      Tensor            w;
      if (!base.valid)
        w = 0; // no linearisation point: the secant tangent
      else
        {
          const double rate_k =
            std::sqrt(2. / 3. * (base.e * base.e)); // at the accepted iterate
          if (!smooth && rate_k <= cutoff)
            w = e / cutoff; // linear law: w = e/cutoff exactly
          else
            {
              // w = n_k + (de - 2/3 w_k (n_k : de)) / r_k, n_k = e_k/r_k: the
              // linearisation of w r = e in (w, e) (doc/theory.md, 4b), with
              // r = rate (piecewise law) or sqrt(rate^2 + cutoff^2) (smooth;
              // its derivative along e is again 2/3 n_k : de).
              const double r  = smooth ? std::hypot(rate_k, cutoff) : rate_k;
              const Tensor n  = base.e / r;
              const Tensor de = e - base.e;
              w               = n + (de - (2. / 3.) * (n * de) * base.w) / r;
            }
        }
      // Project onto the unit ball: the stress cannot exceed the flow stress.
      const double norm = std::sqrt(2. / 3. * (w * w));
      if (norm > 1)
        w /= norm;
      trials[cell * points + q] = PointState{w, e, true};
      return w;
    }
  } // namespace solver
} // namespace formsolve
