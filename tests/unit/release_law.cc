// The springback release's point law (material::ReleaseLaw):
// - within the yield surface it is linear elastic on top of the end stress:
//   stress = end + C : strain, exactly;
// - von Mises, no hardening: the return is the radial one, s = sigma_y
//   s_trial / sigma_bar(s_trial) with the mean stress of the trial (1e-12);
// - von Mises with Swift hardening: sigma_bar = h(eps + d eps_p) and the
//   plastic strain d eps_p = (sigma_bar_trial - sigma_bar)/(3 G) (1e-10);
// - Hill48 in a turned frame: on the yield surface after the return, the
//   stress's change normal to the surface, and the consistent tangent
//   against central differences of the stress (1e-6 relative);
// - the metric of a rotated frame gives the rotated stress's equivalent
//   (a rigidly rotated state keeps its equivalent stress).
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/physics/transformations.h>

#include <formsolve/material/release_law.h>

#include "check.h"

#include <cmath>

using namespace dealii;
using namespace formsolve;

namespace
{
  SymmetricTensor<2, 3> tensor(const double xx,
                               const double yy,
                               const double zz,
                               const double yz,
                               const double xz,
                               const double xy)
  {
    SymmetricTensor<2, 3> t;
    t[0][0] = xx;
    t[1][1] = yy;
    t[2][2] = zz;
    t[1][2] = yz;
    t[0][2] = xz;
    t[0][1] = xy;
    return t;
  }

  Tensor<2, 3> rotation(const double a, const double b)
  {
    // About z by a, then about x by b.
    Tensor<2, 3> Rz, Rx;
    Rz[0][0] = Rz[1][1] = std::cos(a);
    Rz[0][1]            = -std::sin(a);
    Rz[1][0]            = std::sin(a);
    Rz[2][2]            = 1;
    Rx[0][0]            = 1;
    Rx[1][1] = Rx[2][2] = std::cos(b);
    Rx[1][2]            = -std::sin(b);
    Rx[2][1]            = std::sin(b);
    return Rx * Rz;
  }

  parameters::Material steel()
  {
    parameters::Material p;
    p.young_modulus        = 2e5;
    p.poisson_ratio        = 0.3;
    p.strength_coefficient = 500;
    p.hardening_exponent   = 0.2;
    p.prestrain            = 0.01;
    return p;
  }
} // namespace

int main()
{
  const auto                  p = steel();
  const material::ReleaseLaw  law(p);
  const double                G   = law.shear_modulus();
  const Tensor<2, 3>          one = unit_symmetric_tensor<3>();
  const SymmetricTensor<4, 3> P   = law.metric(one);
  const double                eps = 0.1, sy = law.yield_stress(eps);

  // Elastic: inside the surface.
  {
    const auto end    = tensor(0.5 * sy, 0.2 * sy, 0, 0, 0.1 * sy, 0);
    const auto strain = tensor(-1e-4, 2e-5, 1e-5, 0, 0, 3e-5);
    const auto r      = law.respond(end, strain, eps, P);
    const auto diff   = r.stress - end - law.elasticity() * strain;
    test::close("elastic: stress = end + C:strain", diff.norm(), 0, 1e-12);
    test::close("elastic: not yielded", r.yielded, 0, 0);
  }

  // von Mises, radial return (perfectly plastic).
  {
    auto q               = p;
    q.hardening_exponent = 0;
    const material::ReleaseLaw flat(q);
    const double               s0 = flat.yield_stress(0);
    const auto end    = tensor(s0, 0, 0, 0, 0, 0); // uniaxial, on yield
    const auto strain = tensor(-0.02, 0.01, 0.003, 0.002, 0, 0.001);
    const auto trial  = end + flat.elasticity() * strain;
    const auto r      = flat.respond(end, strain, 0, P);
    const auto exact  = s0 /
                         std::sqrt(1.5 * (deviator(trial) * deviator(trial))) *
                         deviator(trial) +
                       trace(trial) / 3 * unit_symmetric_tensor<3>();
    test::close("von Mises: radial return",
                (r.stress - exact).norm() / s0,
                0,
                1e-12);
  }

  // von Mises with hardening: consistency and the plastic strain.
  {
    const auto   end    = tensor(sy, 0, 0, 0, 0, 0);
    const auto   strain = tensor(-0.03, 0.015, 0.015, 0, 0, 0);
    const auto   trial  = end + law.elasticity() * strain;
    const auto   r      = law.respond(end, strain, eps, P);
    const double sb     = law.equivalent(r.stress, P);
    test::close("von Mises: sigma_bar = h(eps + d eps_p)",
                sb / law.yield_stress(eps + r.plastic_strain),
                1,
                1e-12);
    test::close("von Mises: d eps_p = (sigma_bar_trial - sigma_bar)/(3G)",
                r.plastic_strain,
                (law.equivalent(trial, P) - sb) / (3 * G),
                1e-10);
  }

  // Hill48 in a turned frame: surface, normality, tangent.
  {
    auto q                   = p;
    q.anisotropy.criterion   = parameters::YieldCriterion::hill48;
    q.anisotropy.calibration = parameters::HillCalibration::r_values;
    q.anisotropy.r_values    = {2.1, 1.6, 2.7};
    const material::ReleaseLaw hill(q);
    const auto                 R  = rotation(0.4, 0.3);
    const auto                 PH = hill.metric(R);
    const auto end    = tensor(0.9, 0.3, 0.05, 0.1, -0.2, 0.25) * sy;
    const auto endv   = end * (sy / hill.equivalent(end, PH)); // on yield
    const auto strain = tensor(-4e-3, 1e-3, 2e-3, 5e-4, 1e-3, -2e-3);
    const auto r      = hill.respond(endv, strain, eps, PH);
    test::close("Hill48: yielded", r.yielded, 1, 0);
    test::close("Hill48: on the surface after the return",
                hill.equivalent(r.stress, PH) /
                  hill.yield_stress(eps + r.plastic_strain),
                1,
                1e-12);
    // Normality: trial - stress = C : d eps_p with d eps_p along P sigma.
    const auto trial = endv + hill.elasticity() * strain;
    const auto dp    = invert(hill.elasticity()) * (trial - r.stress);
    const auto n     = PH * r.stress;
    test::close("Hill48: plastic strain along P sigma",
                (dp - (dp * n) / (n * n) * n).norm() / dp.norm(),
                0,
                1e-10);
    // Tangent against central differences.
    double worst = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        {
          SymmetricTensor<2, 3> e;
          e[i][j]        = 1e-7;
          const auto up  = hill.respond(endv, strain + e, eps, PH).stress;
          const auto low = hill.respond(endv, strain - e, eps, PH).stress;
          const auto fd  = (up - low) / 2e-7;
          const auto an  = r.tangent * e / 1e-7;
          worst          = std::max(worst, (fd - an).norm() / r.tangent.norm());
        }
    test::close("Hill48: consistent tangent against differences",
                worst,
                0,
                1e-6);
    // A rigidly rotated state keeps its equivalent stress.
    const auto Q  = rotation(-0.7, 0.5);
    const auto PQ = hill.metric(Q * R);
    const auto rotated =
      Physics::Transformations::basis_transformation(r.stress, Q);
    test::close("Hill48: rotated frame and stress",
                hill.equivalent(rotated, PQ) / hill.equivalent(r.stress, PH),
                1,
                1e-12);
  }
  return test::result();
}
