#include <deal.II/base/exceptions.h>

#include <formsolve/solver/dual_stress.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace solver
  {
    void DualStress::reinit(const unsigned int n_cells,
                            const unsigned int n_points)
    {
      points = n_points;
      accepted.assign(n_cells * n_points, PointState());
      trials = accepted;
    }

    void DualStress::reset()
    {
      for (auto &p : accepted)
        p.valid = false;
      trials = accepted;
    }

    void DualStress::restart(const double cutoff)
    {
      for (auto &p : accepted)
        if (p.valid)
          {
            const double rate = std::sqrt(2. / 3. * (p.e * p.e));
            p.w               = p.e / std::max(rate, cutoff);
          }
      trials = accepted;
    }

    DualStress::Tensor DualStress::trial(const unsigned int cell,
                                         const unsigned int q,
                                         const Tensor      &e,
                                         const double       cutoff)
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
          if (rate_k <= cutoff)
            w = e / cutoff; // linear law: w = e/cutoff exactly
          else
            {
              // w = n_k + (de - 2/3 w_k (n_k : de)) / rate_k, n_k = e_k/rate_k:
              // the linearisation of w rate = e in (w, e) (doc/theory.md, 4b).
              const Tensor n  = base.e / rate_k;
              const Tensor de = e - base.e;
              w = n + (de - (2. / 3.) * (n * de) * base.w) / rate_k;
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
