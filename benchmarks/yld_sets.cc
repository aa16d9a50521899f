// Yld2004-18p coefficient sets of the earing cup (doc/forming-results.md):
// for each set given as "name c1 c2" lines on stdin (seven coefficients
// each, comma-separated), the RMS errors against the sheet's data
// (../shared/reference/earing-cup.md: sigma_theta/sigma_0 and r_theta every
// 15 degrees, sigma_b/sigma_0 = 0.975, r_b = 1, sigma_ps/sigma_0 = 1.025),
// and the flow stress of pure shear sigma_r = -sigma_theta at theta (the
// flange's state) over sigma_0 every 15 degrees.
// Run by benchmarks/yld_sets.sh.
#include <formsolve/material/yld2004.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using formsolve::material::Yld2004;

namespace
{
  std::vector<double> coefficients(const std::string &text)
  {
    std::vector<double> v;
    std::istringstream  in(text);
    std::string         item;
    while (std::getline(in, item, ','))
      v.push_back(std::stod(item));
    v.insert(v.begin() + 6, {1., 1.}); // c44 = c55 = 1
    return v;
  }
} // namespace

int main()
{
  const double stress[] = {1.000, 0.944, 0.913, 0.908, 0.898, 0.928, 0.983};
  const double r[]      = {0.526, 0.344, 0.301, 0.253, 0.294, 0.393, 0.601};
  std::string  line;
  while (std::getline(std::cin, line))
    {
      const auto a = line.find(';'), b = line.find(';', a + 1);
      if (a == std::string::npos || b == std::string::npos)
        continue;
      const Yld2004 f(coefficients(line.substr(a + 1, b - a - 1)),
                      coefficients(line.substr(b + 1)),
                      8);
      double        es = 0, er = 0;
      for (unsigned int k = 0; k < 7; ++k)
        {
          const double t = 15. * k * M_PI / 180;
          es += std::pow(f.stress_ratio(t) - stress[k], 2);
          er += std::pow(f.r_value(t) - r[k], 2);
        }
      es += std::pow(f.biaxial_ratio() - 0.975, 2) +
            std::pow(f.plane_strain_ratio() - 1.025, 2);
      er += std::pow(f.biaxial_r() - 1, 2);
      std::printf(
        "%s: RMS %.4f in the 8 stress data (6 angles, sigma_b, sigma_ps), "
        "%.4f in the 8 r-values (7 angles, r_b); pure shear "
        "k/sigma_0 at 0..90 deg:",
        line.substr(0, a).c_str(),
        std::sqrt(es / 8),
        std::sqrt(er / 8));
      for (int t = 0; t <= 90; t += 15)
        {
          const double                th = t * M_PI / 180;
          const Tensor<1, 3>          er_({std::cos(th), std::sin(th), 0.});
          const Tensor<1, 3>          et({-std::sin(th), std::cos(th), 0.});
          const SymmetricTensor<2, 3> s =
            symmetrize(outer_product(er_, er_) - outer_product(et, et));
          std::printf(" %.4f", 1 / f.equivalent(s));
        }
      std::printf("\n");
    }
}
