// One Yld2004-18p local solve (material::solve_dual, doc/theory.md eq. 3e),
// microseconds per call: team 1 of the earing cup (a = 8), 20 000 random
// deviatoric rates, from von Mises's start and warm (from the solution of a
// rate 3 % away, as a Newton iterate gives it); and one evaluation of
// g = sigma_bar^2/2 with its Hessian. Prints the mean local iterations.
#include <formsolve/material/yield_dual.h>
#include <formsolve/material/yld2004.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

using namespace dealii;
using namespace formsolve::material;

int main()
{
  const Yld2004 f(
    {1.1998, 1.2289, 0.1315, 0.8081, 1.1386, 0.2870, 1, 1, 1.3739},
    {1.1510, -0.2576, 0.4873, 0.9934, 0.9110, 0.7965, 1, 1, 0.2679},
    8);
  std::mt19937                     random(1);
  std::normal_distribution<double> normal;
  const unsigned int               n           = 20000;
  auto                             deviator_of = [&]() {
    SymmetricTensor<2, 3> a;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        a[i][j] = normal(random);
    return deviator(a);
  };
  std::vector<SymmetricTensor<2, 3>> e(n), near(n), s(n);
  for (unsigned int k = 0; k < n; ++k)
    {
      e[k]    = deviator_of();
      near[k] = e[k] + 0.03 * e[k].norm() * deviator_of();
    }
  using Clock = std::chrono::steady_clock;
  auto us     = [&](const Clock::time_point a, const Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count() / n * 1e6;
  };
  double        sink = 0;
  unsigned long cold = 0, warm = 0;
  const auto    t0 = Clock::now();
  for (unsigned int k = 0; k < n; ++k)
    {
      const auto d = solve_dual(f, e[k]);
      s[k]         = d.stress;
      cold += d.iterations;
    }
  const auto t1 = Clock::now();
  for (unsigned int k = 0; k < n; ++k)
    {
      const auto d = solve_dual(f, near[k], &s[k]);
      sink += d.rate;
      warm += d.iterations;
    }
  const auto t2 = Clock::now();
  for (unsigned int k = 0; k < n; ++k)
    sink += f.half_square(s[k]).hessian[0][0][0][0];
  const auto t3 = Clock::now();
  std::printf("local solve from von Mises's start %.2f us (%.2f iterations), "
              "warm %.2f us (%.2f iterations); g with its Hessian %.2f us "
              "(checksum %g)\n",
              us(t0, t1),
              double(cold) / n,
              us(t1, t2),
              double(warm) / n,
              us(t2, t3),
              sink);
}
