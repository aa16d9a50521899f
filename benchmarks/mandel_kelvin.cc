// The cost of material/mandel.h's conversions against deal.II's
// Physics::Notation::Kelvin (the same numbers: test mandel_kelvin): a
// symmetric tensor to its 6-vector and back, and a fourth-order one to its
// 6x6 matrix, in ns per call (bash benchmarks/mandel_kelvin.sh).
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/physics/notation.h>

#include <formsolve/material/mandel.h>

#include <chrono>
#include <iostream>
using namespace dealii;
int main()
{
  SymmetricTensor<2, 3> a;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = i; j < 3; ++j)
      a[i][j] = 1.0 + i + 0.3 * j;
  SymmetricTensor<4, 3> C  = identity_tensor<3>() + outer_product(a, a);
  const int             n  = 2000000;
  double                s  = 0;
  auto                  t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k)
    {
      a[0][0] += 1e-9;
      const auto v = formsolve::material::to_mandel(a);
      s += v[3];
      const auto b = formsolve::material::from_mandel(v);
      s += b[1][2];
    }
  auto t1 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k)
    {
      a[0][0] += 1e-9;
      const auto v = Physics::Notation::Kelvin::to_vector(a);
      s += v[3];
      const auto b =
        Physics::Notation::Kelvin::to_tensor<SymmetricTensor<2, 3>>(v);
      s += b[1][2];
    }
  auto t2 = std::chrono::steady_clock::now();
  for (int k = 0; k < n / 10; ++k)
    {
      C[0][0][0][0] += 1e-9;
      const auto m = formsolve::material::to_mandel(C);
      s += m[3][3];
    }
  auto t3 = std::chrono::steady_clock::now();
  for (int k = 0; k < n / 10; ++k)
    {
      C[0][0][0][0] += 1e-9;
      const auto m = Physics::Notation::Kelvin::to_matrix(C);
      s += m(3, 3);
    }
  auto t4 = std::chrono::steady_clock::now();
  // agreement
  const auto v1 = formsolve::material::to_mandel(a);
  const auto v2 = Physics::Notation::Kelvin::to_vector(a);
  double     d  = 0;
  for (int r = 0; r < 6; ++r)
    d = std::max(d, std::abs(v1[r] - v2[r]));
  const auto m1 = formsolve::material::to_mandel(C);
  const auto m2 = Physics::Notation::Kelvin::to_matrix(C);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      d = std::max(d, std::abs(m1[r][c] - m2(r, c)));
  using ns = std::chrono::nanoseconds;
  std::cout << "vector round trip: mandel "
            << std::chrono::duration_cast<ns>(t1 - t0).count() / double(n)
            << " ns, Kelvin "
            << std::chrono::duration_cast<ns>(t2 - t1).count() / double(n)
            << " ns\n"
            << "6x6 matrix: mandel "
            << std::chrono::duration_cast<ns>(t3 - t2).count() / double(n / 10)
            << " ns, Kelvin "
            << std::chrono::duration_cast<ns>(t4 - t3).count() / double(n / 10)
            << " ns\n"
            << "largest difference " << d << " (" << s << ")\n";
}
