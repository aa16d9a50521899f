// The in-plane uniaxial stress of a directional tensile test, shared by the
// anisotropic criteria's r-values and stress ratios (Hill48, Yld2004-18p).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace formsolve
{
  namespace material
  {
    /// The uniaxial stress of unit size along @p angle (radians) to RD in
    /// the RD-TD plane of the orthotropy frame.
    inline dealii::SymmetricTensor<2, 3> uniaxial_stress(const double angle)
    {
      const double                  c = std::cos(angle), s = std::sin(angle);
      dealii::SymmetricTensor<2, 3> sigma;
      sigma[0][0] = c * c;
      sigma[1][1] = s * s;
      sigma[0][1] = c * s;
      return sigma;
    }
  } // namespace material
} // namespace formsolve
