// A deviatoric strain rate of equivalent rate r for the point-law tests:
// plane strain in x-y plus a little shear, so that D' (x) D' is not diagonal.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace test
{
  inline dealii::SymmetricTensor<2, 3> rate_of(const double r)
  {
    dealii::SymmetricTensor<2, 3> d;
    d[0][0] = 1;
    d[1][1] = -0.6;
    d[2][2] = -0.4;
    d[0][1] = 0.3;
    d[1][2] = -0.2;
    return d * (r / std::sqrt(2. / 3. * (d * d)));
  }
} // namespace test
