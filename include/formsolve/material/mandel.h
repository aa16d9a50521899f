// Symmetric 3x3 tensors as 6-vectors and their fourth-order maps as 6x6
// matrices (Mandel's notation: the shear entries carry sqrt 2), so that
// A : C : B = a^T C b and the products of a general material tangent are
// small dense ones.
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>

namespace formsolve
{
  namespace material
  {
    using Mandel6   = std::array<double, 6>;
    using Mandel6x6 = std::array<std::array<double, 6>, 6>;

    /// (i, j) of Mandel entry r: the diagonal, then (1,2), (0,2), (0,1).
    constexpr std::array<std::array<unsigned int, 2>, 6> mandel_index = {
      {{{0, 0}}, {{1, 1}}, {{2, 2}}, {{1, 2}}, {{0, 2}}, {{0, 1}}}};

    inline double mandel_factor(const unsigned int r)
    {
      return r < 3 ? 1. : std::sqrt(2.);
    }

    inline Mandel6 to_mandel(const dealii::SymmetricTensor<2, 3> &a)
    {
      Mandel6 v;
      for (unsigned int r = 0; r < 6; ++r)
        v[r] = mandel_factor(r) * a[mandel_index[r][0]][mandel_index[r][1]];
      return v;
    }

    inline Mandel6x6 to_mandel(const dealii::SymmetricTensor<4, 3> &C)
    {
      Mandel6x6 m;
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          m[r][s] = mandel_factor(r) * mandel_factor(s) *
                    C[mandel_index[r][0]][mandel_index[r][1]]
                     [mandel_index[s][0]][mandel_index[s][1]];
      return m;
    }

    inline dealii::SymmetricTensor<2, 3> from_mandel(const Mandel6 &v)
    {
      dealii::SymmetricTensor<2, 3> a;
      for (unsigned int r = 0; r < 6; ++r)
        a[mandel_index[r][0]][mandel_index[r][1]] = v[r] / mandel_factor(r);
      return a;
    }

    /// The fourth-order tensor of a 6x6 matrix (minor symmetries only).
    inline dealii::SymmetricTensor<4, 3> from_mandel(const Mandel6x6 &m)
    {
      dealii::SymmetricTensor<4, 3> C;
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          C[mandel_index[r][0]][mandel_index[r][1]][mandel_index[s][0]]
           [mandel_index[s][1]] =
             m[r][s] / (mandel_factor(r) * mandel_factor(s));
      return C;
    }

    inline Mandel6 multiply(const Mandel6x6 &A, const Mandel6 &x)
    {
      Mandel6 y{};
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          y[r] += A[r][s] * x[s];
      return y;
    }

    /// A B, and A B^T.
    Mandel6x6 multiply(const Mandel6x6 &A, const Mandel6x6 &B);
    Mandel6x6 multiply_transpose(const Mandel6x6 &A, const Mandel6x6 &B);
    /// A^T x.
    Mandel6 transpose_multiply(const Mandel6x6 &A, const Mandel6 &x);

    /// T with to_mandel(R a R^T) = T to_mandel(a) for symmetric a: a
    /// rotation of the 6-space (T^T = T^-1) when R is orthogonal.
    Mandel6x6 mandel_rotation(const dealii::Tensor<2, 3> &R);
  } // namespace material
} // namespace formsolve
