#include <formsolve/material/damage.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    DamageCriteria::DamageCriteria(const parameters::Material &p)
        : a(p.oyane_a)
        , b(p.oyane_b)
        , critical(p.cockcroft_latham)
        , which(p.fracture)
    {}

    DamageIncrement DamageCriteria::increment(const SymmetricTensor<2, 3> &s,
                                              const double                 mean,
                                              const double d_strain) const
    {
      DamageIncrement d;
      const double    equivalent = std::sqrt(1.5 * (s * s));
      if (d_strain <= 0 || equivalent <= 0)
        return d;
      d.oyane                     = (mean / equivalent + a) * d_strain / b;
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
