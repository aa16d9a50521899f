#include <formsolve/material/mandel.h>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    Mandel6x6 multiply(const Mandel6x6 &A, const Mandel6x6 &B)
    {
      Mandel6x6 C{};
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int k = 0; k < 6; ++k)
          for (unsigned int s = 0; s < 6; ++s)
            C[r][s] += A[r][k] * B[k][s];
      return C;
    }

    Mandel6x6 multiply_transpose(const Mandel6x6 &A, const Mandel6x6 &B)
    {
      Mandel6x6 C{};
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          for (unsigned int k = 0; k < 6; ++k)
            C[r][s] += A[r][k] * B[s][k];
      return C;
    }

    Mandel6 transpose_multiply(const Mandel6x6 &A, const Mandel6 &x)
    {
      Mandel6 y{};
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          y[s] += A[r][s] * x[r];
      return y;
    }

    Mandel6x6 mandel_rotation(const Tensor<2, 3> &R)
    {
      // Column s: the rotated basis tensor E_s (unit in Mandel's norm).
      Mandel6x6 T{};
      for (unsigned int s = 0; s < 6; ++s)
        {
          Mandel6 e{};
          e[s]                           = 1;
          const SymmetricTensor<2, 3> E  = from_mandel(e);
          Tensor<2, 3>                RE = R * Tensor<2, 3>(E) * transpose(R);
          const Mandel6               t  = to_mandel(symmetrize(RE));
          for (unsigned int r = 0; r < 6; ++r)
            T[r][s] = t[r];
        }
      return T;
    }
  } // namespace material
} // namespace formsolve
