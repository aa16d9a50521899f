// Hill 1948 (material/hill48.cc) against closed forms:
// - r = 1 is von Mises: P = 3/2 and Q = 2/3 of the deviatoric projector;
// - the r-values of uniaxial tension at 0, 45 and 90 degrees to RD (flow
//   rule D ~ P : sigma) are the input ones, and the flow stress ratio is
//   Hill's 1/sqrt(F s^4 + G c^4 + H (c^2 - s^2)^2 + 2 N s^2 c^2);
// - Q is P's inverse on deviators: Q : (P : s') = s', the plastic work
//   s' : D = sigma_bar eps_bar_dot, and Q annihilates the identity;
// - normal anisotropy: eps_bar_dot^2 of in-plane principal rates is
//   (1+r)/(1+2r) [(1+r)(e1^2 + e2^2) + 2 r e1 e2];
// - a metric rotated with the material gives the same equivalent rate;
// - the 6-vectors and 6x6 matrices of material/mandel.h are deal.II's Kelvin
//   notation (Physics::Notation::Kelvin: same order, same sqrt 2), kept in
//   fixed-size arrays because Kelvin's heap Vector/FullMatrix cost 4-5x
//   per point; mandel_rotation rotates them as R a R^T.
#include <deal.II/physics/notation.h>
#include <deal.II/physics/transformations.h>

#include <formsolve/material/hill48.h>
#include <formsolve/material/mandel.h>

#include "check.h"

#include <array>
#include <cmath>
#include <string>

using namespace dealii;
using formsolve::material::Hill48;
using formsolve::material::TransverseShear;

namespace
{
  double largest_difference(const SymmetricTensor<4, 3> &a,
                            const SymmetricTensor<4, 3> &b)
  {
    double d = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            d = std::max(d, std::abs(a[i][j][k][l] - b[i][j][k][l]));
    return d;
  }

  SymmetricTensor<2, 3> some_deviator(const double seed)
  {
    SymmetricTensor<2, 3> s;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        s[i][j] = std::sin(seed * (1 + 3 * i + j));
    return deviator(s);
  }

  void check_metrics(const std::string &name, const Hill48 &h)
  {
    const auto P = h.primal(), Q = h.dual();
    for (const double seed : {0.7, 1.3, 2.9})
      {
        const auto   s    = some_deviator(seed);
        const auto   D    = P * s;
        const double bar  = std::sqrt(s * (P * s)),
                     rate = std::sqrt(D * (Q * D));
        test::close(name + ": Q : (P : s') = s'",
                    (Q * D - s).norm() / s.norm(),
                    0,
                    1e-12);
        test::close(name + ": s' : D = sigma_bar eps_bar_dot",
                    s * D,
                    bar * rate,
                    1e-12 * bar * rate);
      }
    test::close(name + ": Q : I = 0",
                (Q * unit_symmetric_tensor<3>()).norm(),
                0,
                1e-14);
  }
} // namespace

int main()
{
  const double pi = std::acos(-1.);
  {
    const Hill48 h   = Hill48::from_normal_r(1., TransverseShear::equal_to_n);
    const auto   dev = deviator_tensor<3>();
    test::close("r = 1: P = 3/2 dev",
                largest_difference(h.primal(), 1.5 * dev),
                0,
                1e-15);
    test::close("r = 1: Q = 2/3 dev",
                largest_difference(h.dual(), 2. / 3 * dev),
                0,
                1e-15);
    test::close("r = 1: the r-value at 30 degrees",
                h.r_value(pi / 6),
                1,
                1e-14);
    check_metrics("r = 1", h);
  }
  for (const auto &[r0, r45, r90] : {std::array<double, 3>{{1.9, 1.4, 2.3}},
                                     std::array<double, 3>{{0.6, 0.5, 0.7}},
                                     std::array<double, 3>{{0.85, 0.85, 0.85}}})
    {
      const std::string name = "r " + std::to_string(r0) + ", " +
                               std::to_string(r45) + ", " + std::to_string(r90);
      const Hill48 h =
        Hill48::from_r_values(r0, r45, r90, TransverseShear::equal_to_n);
      test::close(name + ": r at 0", h.r_value(0), r0, 1e-12 * r0);
      test::close(name + ": r at 45", h.r_value(pi / 4), r45, 1e-12 * r45);
      test::close(name + ": r at 90", h.r_value(pi / 2), r90, 1e-12 * r90);
      test::close(name + ": G + H = 1", h.G + h.H, 1, 1e-15);
      for (const double angle : {pi / 8, pi / 4, pi / 2})
        {
          const double c = std::cos(angle), s = std::sin(angle);
          const double hill =
            1 / std::sqrt(h.F * std::pow(s, 4) + h.G * std::pow(c, 4) +
                          h.H * std::pow(c * c - s * s, 2) +
                          2 * h.N * s * s * c * c);
          test::close(name + ": stress ratio at " + std::to_string(angle),
                      h.stress_ratio(angle),
                      hill,
                      1e-13);
        }
      check_metrics(name, h);
      // A rotation of the material and of the rate together changes nothing.
      const double       a = 0.4, b = 1.1;
      const Tensor<2, 3> Rz({{std::cos(a), -std::sin(a), 0},
                             {std::sin(a), std::cos(a), 0},
                             {0, 0, 1}});
      const Tensor<2, 3> Rx({{1, 0, 0},
                             {0, std::cos(b), -std::sin(b)},
                             {0, std::sin(b), std::cos(b)}});
      const Tensor<2, 3> R  = Rz * Rx;
      const auto         D  = some_deviator(0.3);
      const auto         Dc = symmetrize(R * Tensor<2, 3>(D) * transpose(R));
      const auto         Qc =
        dealii::Physics::Transformations::basis_transformation(h.dual(), R);
      test::close(name + ": rotated with the material",
                  Dc * (Qc * Dc),
                  D * (h.dual() * D),
                  1e-13 * (D * (h.dual() * D)));
    }
  {
    const double r = 0.85, e1 = 0.7, e2 = -0.2;
    const Hill48 h = Hill48::from_normal_r(r, TransverseShear::isotropic);
    SymmetricTensor<2, 3> D;
    D[0][0] = e1;
    D[1][1] = e2;
    D[2][2] = -e1 - e2;
    const double closed =
      (1 + r) / (1 + 2 * r) * ((1 + r) * (e1 * e1 + e2 * e2) + 2 * r * e1 * e2);
    test::close("normal r: eps_bar_dot^2 of in-plane rates",
                D * (h.dual() * D),
                closed,
                1e-14);
    test::close("normal r, L = M = 3/2", h.L + h.M, 3, 0);
  }
  {
    namespace Kelvin = Physics::Notation::Kelvin;
    using namespace formsolve::material;
    const SymmetricTensor<2, 3> a =
      some_deviator(0.3) + unit_symmetric_tensor<3>();
    const Hill48 h = Hill48::from_normal_r(0.7, TransverseShear::isotropic);
    const SymmetricTensor<4, 3> C  = h.dual() + outer_product(a, a);
    const Vector<double>        kv = Kelvin::to_vector(a);
    const FullMatrix<double>    km = Kelvin::to_matrix(C);
    const Mandel6               mv = to_mandel(a);
    const Mandel6x6             mm = to_mandel(C);
    double                      dv = 0, dm = 0;
    for (unsigned int r = 0; r < 6; ++r)
      {
        dv = std::max(dv, std::abs(mv[r] - kv[r]));
        for (unsigned int c = 0; c < 6; ++c)
          dm = std::max(dm, std::abs(mm[r][c] - km(r, c)));
      }
    test::close("Mandel 6-vector is Kelvin's", dv, 0, 1e-15);
    test::close("Mandel 6x6 matrix is Kelvin's", dm, 0, 1e-14);
    const SymmetricTensor<2, 3> back =
      Kelvin::to_tensor<SymmetricTensor<2, 3>>(kv);
    test::close("from_mandel is Kelvin's to_tensor",
                (from_mandel(mv) - back).norm(),
                0,
                1e-15);
    Tensor<1, 3> axis({0.3, 0.5, 0.8});
    axis /= axis.norm();
    const Tensor<2, 3> R =
      Physics::Transformations::Rotations::rotation_matrix_3d(axis, 0.4);
    const Mandel6 rotated = multiply(mandel_rotation(R), to_mandel(a));
    const SymmetricTensor<2, 3> Ra =
      Physics::Transformations::basis_transformation(a, R);
    test::close("mandel_rotation is R a R^T",
                (from_mandel(rotated) - Ra).norm(),
                0,
                1e-14);
  }
  return test::result();
}
