// Yld2004-18p and Hosford (material/yld2004.cc, material/yield_dual.cc)
// against closed forms and the reference's printed values:
// - unit coefficients and a = 2 are von Mises: sigma_bar, the Hessian of
//   sigma_bar^2/2 (3/2 P_dev) and the dual solve (s = 2/3 D', the rate
//   sqrt(2/3 D':D'), compliance 2/3 P_dev) to 1e-12;
// - unit coefficients and a = 6 give Hosford's plane-strain and shear
//   ratios (2/(1 + 2^(1-a)))^(1/a) and (2/(2^a + 2))^(1/a);
// - the two published coefficient sets of ../shared/reference/earing-cup.md
//   reproduce the printed sigma_theta/sigma_0 and r_theta every 15 degrees
//   (to 1e-3);
// - convexity: grad^2 g positive definite on deviators at 2000 stress
//   directions, for every set;
// - the dual solve does the plastic work s : D' = sigma_bar(s) rate, its
//   compliance is the derivative of s (finite differences), and its
//   gradient inverts the solve (grad g(s) = D'), also at a = 30 (nearly
//   flat faces, the capped Newton step).
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/physics/notation.h>

#include <formsolve/material/yield_dual.h>
#include <formsolve/material/yld2004.h>

#include "check.h"

#include <cmath>
#include <string>
#include <vector>

using namespace dealii;
using formsolve::material::from_mandel;
using formsolve::material::solve_dual;
using formsolve::material::Yld2004;

namespace
{
  SymmetricTensor<2, 3> some_deviator(const double seed)
  {
    SymmetricTensor<2, 3> s;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        s[i][j] = std::sin(seed * (1 + 3 * i + j) + 0.3 * i);
    return deviator(s);
  }

  double largest(const SymmetricTensor<4, 3> &a)
  {
    double d = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            d = std::max(d, std::abs(a[i][j][k][l]));
    return d;
  }

  /// The seven published coefficients to nine (c44 = c55 = 1).
  std::vector<double> nine(std::vector<double> c)
  {
    c.insert(c.begin() + 6, {1., 1.});
    return c;
  }

  Yld2004 team(const unsigned int t)
  {
    if (t == 1)
      return Yld2004(
        nine({1.1998, 1.2289, 0.1315, 0.8081, 1.1386, 0.2870, 1.3739}),
        nine({1.1510, -0.2576, 0.4873, 0.9934, 0.9110, 0.7965, 0.2679}),
        8);
    return Yld2004(nine({1.0, 1.0, -0.0870, 0.4496, 1.0192, 1.1724, 0.0}),
                   nine(
                     {1.3329, 1.2510, 1.0948, 1.0855, -0.0065, 0.4812, 1.5461}),
                   8);
  }

  void check_von_mises()
  {
    const Yld2004 f = Yld2004::hosford(2);
    for (const double seed : {0.4, 1.1, 2.7})
      {
        const auto s = some_deviator(seed);
        test::close("a = 2: sigma_bar is von Mises's",
                    f.equivalent(s + 3. * unit_symmetric_tensor<3>()),
                    std::sqrt(1.5 * (s * s)),
                    1e-12);
        const auto g = f.half_square(s);
        test::close("a = 2: Hessian of g is 3/2 P_dev",
                    largest(g.hessian - 1.5 * deviator_tensor<3>()),
                    0,
                    1e-12);
        const auto d = solve_dual(f, s);
        test::close("a = 2: s = 2/3 D'",
                    (d.stress - (2. / 3.) * s).norm(),
                    0,
                    1e-12);
        test::close("a = 2: rate", d.rate, std::sqrt(2. / 3. * (s * s)), 1e-12);
        test::close("a = 2: compliance 2/3 P_dev",
                    largest(from_mandel(d.compliance) -
                            (2. / 3.) * deviator_tensor<3>()),
                    0,
                    1e-12);
      }
  }

  void check_hosford(const double a)
  {
    const Yld2004         f = Yld2004::hosford(a);
    SymmetricTensor<2, 3> D;
    D[0][0] = 1, D[2][2] = -1; // plane strain
    auto s = solve_dual(f, D).stress;
    test::close("Hosford a = " + std::to_string(int(a)) +
                  ": plane-strain ratio",
                (s[0][0] - s[2][2]) / f.equivalent(s),
                std::pow(2 / (1 + std::pow(2, 1 - a)), 1 / a),
                1e-12);
    test::close("... and its middle stress is half the largest",
                (s[1][1] - s[2][2]) / (s[0][0] - s[2][2]),
                0.5,
                1e-12);
    D[2][2] = 0, D[1][1] = -1; // pure shear
    s = solve_dual(f, D).stress;
    test::close("Hosford a = " + std::to_string(int(a)) + ": shear ratio",
                s[0][0] / f.equivalent(s),
                std::pow(2 / (std::pow(2, a) + 2), 1 / a),
                1e-12);
    test::close("... r-value 1 at 0 and 45 degrees",
                std::abs(f.r_value(0) - 1) + std::abs(f.r_value(M_PI / 4) - 1),
                0,
                1e-12);
  }

  void check_published(const unsigned int t)
  {
    const std::vector<std::vector<double>> ratio = {
      {1.000, 0.953, 0.904, 0.898, 0.900, 0.941, 0.969},
      {1.000, 0.974, 0.927, 0.903, 0.918, 0.958, 0.982}};
    const std::vector<std::vector<double>> r = {
      {0.523, 0.355, 0.301, 0.242, 0.310, 0.382, 0.600},
      {0.497, 0.399, 0.282, 0.264, 0.318, 0.456, 0.557}};
    const Yld2004 f = team(t);
    for (unsigned int k = 0; k < 7; ++k)
      {
        const double      angle = 15. * k * M_PI / 180;
        const std::string name =
          "team " + std::to_string(t) + " at " + std::to_string(15 * k);
        test::close(name + ": sigma/sigma0",
                    f.stress_ratio(angle),
                    ratio[t - 1][k],
                    1e-3);
        test::close(name + ": r", f.r_value(angle), r[t - 1][k], 1e-3);
      }
  }

  /// The smallest eigenvalue of grad^2 g + P_h over stress directions.
  void check_convex(const std::string &name, const Yld2004 &f)
  {
    const SymmetricTensor<4, 3> Ph =
      outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>()) /
      3.;
    double smallest = 1e300;
    for (unsigned int k = 0; k < 2000; ++k)
      {
        const auto s = some_deviator(0.01 + 0.173 * k);
        if (s.norm() < 1e-3)
          continue;
        LAPACKFullMatrix<double> H(6, 6);
        H = Physics::Notation::Kelvin::to_matrix(f.half_square(s).hessian + Ph);
        H.compute_eigenvalues();
        for (unsigned int i = 0; i < 6; ++i)
          smallest = std::min(smallest, H.eigenvalue(i).real());
      }
    std::cout << name << ": smallest curvature " << smallest << "\n";
    test::close(name + ": strictly convex (smallest curvature > 1e-8, the "
                       "start-up check's bound)",
                smallest > 1e-8,
                1,
                0);
  }

  void check_dual(const std::string &name, const Yld2004 &f)
  {
    for (const double seed : {0.3, 1.9, 4.4})
      {
        const auto e = 0.7 * some_deviator(seed);
        const auto d = solve_dual(f, e);
        test::close(name + ": s : D' = sigma_bar rate",
                    d.stress * e,
                    f.equivalent(d.stress) * d.rate,
                    1e-12 * d.rate * d.rate);
        test::close(name + ": grad g(s) = D'",
                    (f.half_square(d.stress).gradient - e).norm(),
                    0,
                    1e-12);
        double       err = 0;
        const double h   = 1e-6;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            {
              SymmetricTensor<2, 3> de;
              de[i][j]                       = h;
              const auto                  p  = solve_dual(f, e + de).stress;
              const auto                  m  = solve_dual(f, e - de).stress;
              const SymmetricTensor<2, 3> fd = (p - m) / (2 * h);
              const SymmetricTensor<2, 3> an =
                from_mandel(d.compliance) *
                deviator(SymmetricTensor<2, 3>(de / h));
              err =
                std::max(err,
                         (fd - an).norm() / from_mandel(d.compliance).norm());
            }
        test::close(name + ": compliance against finite differences",
                    err,
                    0,
                    1e-6);
      }
  }
} // namespace

int main()
{
  check_von_mises();
  check_hosford(6);
  check_hosford(8);
  check_published(1);
  check_published(2);
  check_convex("team 1", team(1));
  check_convex("team 2", team(2));
  check_convex("Hosford a = 6", Yld2004::hosford(6));
  check_dual("team 1", team(1));
  check_dual("team 2", team(2));
  check_dual("Hosford a = 8", Yld2004::hosford(8));
  // The largest exponent accepted: nearly flat faces, a Newton step from
  // the von Mises start far longer than s (capped), pure shear on a face.
  check_convex("Hosford a = 30", Yld2004::hosford(30));
  check_dual("Hosford a = 30", Yld2004::hosford(30));
  SymmetricTensor<2, 3> shear;
  shear[0][0] = 1, shear[1][1] = -1;
  const auto d = solve_dual(Yld2004::hosford(30), shear);
  test::close(
    "Hosford a = 30, pure shear: grad g(s) = D'",
    (Yld2004::hosford(30).half_square(d.stress).gradient - shear).norm(),
    0,
    1e-12);
  return test::result();
}
