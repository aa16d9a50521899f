#include <formsolve/material/damage.h>
#include <formsolve/material/hill48.h>
#include <formsolve/material/yld2004.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    namespace
    {
      /// sigma_bar_calibrated = sigma_bar / k, eps_bar_calibrated = k
      /// eps_bar for Hill's normal anisotropy with r (anisotropy.md 4).
      double normalisation(const parameters::Anisotropy &p, const double r)
      {
        if (p.criterion == parameters::YieldCriterion::von_mises ||
            p.damage_normalisation ==
              parameters::DamageNormalisation::rolling_direction)
          return 1;
        return std::sqrt(2 * (2 + r) / (3 * (1 + r)));
      }

      double mean_r(const parameters::Anisotropy &p)
      {
        if (p.criterion == parameters::YieldCriterion::von_mises)
          return 1;
        return p.non_quadratic() ? Yld2004::from_parameters(p).mean_r()
                                 : Hill48::from_parameters(p).mean_r();
      }
    } // namespace

    DamageCriteria::DamageCriteria(const parameters::Material &p)
        : DamageCriteria(p, mean_r(p.anisotropy))
    {}

    DamageCriteria::DamageCriteria(const parameters::Material &p,
                                   const double                mean_r)
        : k(normalisation(p.anisotropy, mean_r))
        , a(p.oyane_a / k)
        , b(p.oyane_b / (k * k))
        , critical(p.cockcroft_latham / k)
        , which(p.fracture)
        , mean(p.mean_stress)
    {}

    DamageIncrement DamageCriteria::increment(const SymmetricTensor<2, 3> &s,
                                              const double                 mean,
                                              const double equivalent,
                                              const double d_strain) const
    {
      DamageIncrement d;
      if (d_strain <= 0 || equivalent <= 0)
        return d;
      // Oyane's integral needs its constants (not given: NaN, left at 0).
      if (std::isfinite(a) && std::isfinite(b))
        d.oyane = (mean / equivalent + a) * d_strain / b;
      SymmetricTensor<2, 3> sigma = s;
      for (unsigned int i = 0; i < 3; ++i)
        sigma[i][i] += mean;
      const auto principal = eigenvalues(sigma); // descending
      d.cockcroft_latham   = std::max(principal[0], 0.) * d_strain;
      return d;
    }

    double DamageCriteria::deciding(const double oyane,
                                    const double integral) const
    {
      switch (which)
        {
          case parameters::FractureCriterion::oyane:
            return oyane;
          case parameters::FractureCriterion::cockcroft_latham:
            return cockcroft_latham(integral);
          case parameters::FractureCriterion::none:
            return 0;
        }
      return 0;
    }
  } // namespace material
} // namespace formsolve
