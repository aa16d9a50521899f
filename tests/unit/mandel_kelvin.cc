// material/mandel.h is deal.II's Kelvin notation (Physics::Notation::Kelvin:
// the same order of the six entries, the shear ones times sqrt 2) held in
// fixed-size arrays: for random symmetric tensors of order 2 and 4 both give
// the same 6-vectors and 6x6 matrices and back, and the 6x6 rotation maps a
// tensor's vector to that of the rotated tensor. The hand-written arrays stay
// because deal.II 9.4 returns heap Vector/FullMatrix (doc/theory.md, 5a:
// measured 100x slower on the vector round trip).
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/physics/notation.h>
#include <deal.II/physics/transformations.h>

#include <formsolve/material/mandel.h>

#include "check.h"

#include <cmath>
#include <random>

using namespace dealii;
namespace kelvin = Physics::Notation::Kelvin;

int main()
{
  std::mt19937                           rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  double                                 v = 0, m = 0, back = 0, rot = 0;
  for (unsigned int k = 0; k < 20; ++k)
    {
      SymmetricTensor<2, 3> a, b;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          {
            a[i][j] = u(rng);
            b[i][j] = u(rng);
          }
      const SymmetricTensor<4, 3> C =
        outer_product(a, b) + outer_product(b, a) + identity_tensor<3>();
      const auto va = formsolve::material::to_mandel(a);
      const auto ka = kelvin::to_vector(a);
      for (unsigned int r = 0; r < 6; ++r)
        v = std::max(v, std::abs(va[r] - ka[r]));
      const auto mc = formsolve::material::to_mandel(C);
      const auto kc = kelvin::to_matrix(C);
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int s = 0; s < 6; ++s)
          m = std::max(m, std::abs(mc[r][s] - kc(r, s)));
      back = std::max(back,
                      (formsolve::material::from_mandel(va) -
                       kelvin::to_tensor<SymmetricTensor<2, 3>>(ka))
                        .norm());
      back = std::max(back,
                      (formsolve::material::from_mandel(mc) -
                       kelvin::to_tensor<SymmetricTensor<4, 3>>(kc))
                        .norm());
      // A rotation about an axis in general position.
      Tensor<1, 3> n({u(rng), u(rng), 1.});
      n /= n.norm();
      const Tensor<2, 3> R =
        Physics::Transformations::Rotations::rotation_matrix_3d(n, 3 * u(rng));
      const auto T  = formsolve::material::mandel_rotation(R);
      const auto Ta = formsolve::material::multiply(T, va);
      const auto kr =
        kelvin::to_vector(symmetrize(R * Tensor<2, 3>(a) * transpose(R)));
      for (unsigned int r = 0; r < 6; ++r)
        rot = std::max(rot, std::abs(Ta[r] - kr[r]));
    }
  test::close("2nd order: Kelvin's vector", v, 0, 1e-15);
  test::close("4th order: Kelvin's 6x6 matrix", m, 0, 4e-15);
  test::close("back to the tensors", back, 0, 1e-14);
  test::close("the 6x6 rotation: Kelvin's vector of the rotated tensor",
              rot,
              0,
              1e-14);
  return test::result();
}
