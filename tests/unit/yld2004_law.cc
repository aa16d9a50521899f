// The rigid-viscoplastic point law with a non-quadratic criterion
// (RigidViscoplastic::respond_dual, doc/theory.md eqs. 3e, 3f):
// - Hosford a = 2 (Yld2004-18p with unit coefficients) gives von Mises's
//   stress and general tangent to 1e-12, plastic and rigid, Newton and secant,
//   piecewise and smooth rigid zones;
// - the plastic work sigma' : D = sigma_bar eps_bar_dot (1e-12) with the
//   published team 1 set;
// - the tangent against central differences of the stress, with
//   hardening, rate sensitivity, plastic and rigid points and a dual
//   direction equal to the pseudo-rate (Newton's tangent; 1e-8, the
//   differences' own error is about 1e-10);
// - a rotated material frame with a rotated rate gives the rotated stress.
#include <deal.II/base/tensor.h>

#include <formsolve/material/rigid_viscoplastic.h>

#include "check.h"
#include "point_rate.h"

#include <cmath>
#include <string>

using namespace dealii;
using namespace formsolve;
using material::Mandel6x6;

namespace
{
  using test::rate_of;

  Tensor<2, 3> rotation(const double a, const double b)
  {
    Tensor<2, 3> Rz, Rx;
    Rz[0][0] = Rz[1][1] = std::cos(a);
    Rz[0][1] = -std::sin(a), Rz[1][0] = std::sin(a), Rz[2][2] = 1;
    Rx[1][1] = Rx[2][2] = std::cos(b);
    Rx[1][2] = -std::sin(b), Rx[2][1] = std::sin(b), Rx[0][0] = 1;
    return Rz * Rx;
  }

  SymmetricTensor<2, 3> times(const Mandel6x6             &C,
                              const SymmetricTensor<2, 3> &d)
  {
    return material::from_mandel(material::multiply(C, material::to_mandel(d)));
  }

  parameters::Material law(const parameters::YieldCriterion c,
                           const double                     a,
                           const parameters::RigidZone      zone)
  {
    parameters::Material p;
    p.limiting_strain_rate      = 1e-4;
    p.rate_sensitivity          = 0.02;
    p.rigid_zone                = zone;
    p.anisotropy.criterion      = c;
    p.anisotropy.yield_exponent = a;
    if (c == parameters::YieldCriterion::yld2004_18p)
      {
        p.anisotropy
          .yld_c1 = {1.1998, 1.2289, 0.1315, 0.8081, 1.1386, 0.2870, 1.3739};
        p.anisotropy
          .yld_c2 = {1.1510, -0.2576, 0.4873, 0.9934, 0.9110, 0.7965, 0.2679};
      }
    return p;
  }

  void check_von_mises(const parameters::RigidZone zone, const std::string &tag)
  {
    using parameters::YieldCriterion;
    const material::RigidViscoplastic vm(
      law(YieldCriterion::von_mises, 2, zone));
    const material::RigidViscoplastic h2(law(YieldCriterion::hosford, 2, zone));
    const Mandel6x6 I = h2.hill_map(Tensor<2, 3>(unit_symmetric_tensor<3>()));
    for (const double r : {3e-5, 1e-2, 1.})
      for (const bool newton : {false, true})
        {
          const auto        D    = rate_of(r);
          const auto        a    = vm.evaluate(D, 0.1, 0.25, newton);
          const auto        b    = h2.evaluate(D, 0.1, 0.25, newton, I);
          const std::string name = tag + ", r = " + std::to_string(r) +
                                   (newton ? ", Newton" : ", secant");
          test::close("Hosford a = 2 is von Mises: stress (" + name + ")",
                      (a.deviatoric_stress - b.deviatoric_stress).norm() /
                        a.deviatoric_stress.norm(),
                      0,
                      1e-12);
          const auto e  = deviator(D);
          const auto ta = vm.tangent(a, e);
          const auto tb =
            material::from_mandel(h2.tangent(b, b.strain_rate_deviator, I));
          test::close("... tangent (" + name + ")",
                      (ta - tb).norm() / ta.norm(),
                      0,
                      1e-12);
        }
  }

  void check_team1(const parameters::RigidZone zone, const std::string &tag)
  {
    const material::RigidViscoplastic yld(
      law(parameters::YieldCriterion::yld2004_18p, 8, zone));
    const Mandel6x6 I = yld.hill_map(Tensor<2, 3>(unit_symmetric_tensor<3>()));
    for (const double r : {3e-5, 1e-2, 1.})
      {
        const auto        D    = rate_of(r);
        const auto        m    = yld.evaluate(D, 0.1, 0.25, true, I);
        const std::string name = tag + ", r = " + std::to_string(r);
        test::close("team 1: sigma' : D = sigma_bar rate (" + name + ")",
                    m.deviatoric_stress * D,
                    m.flow_stress * m.equivalent_strain_rate,
                    1e-12 * m.flow_stress * m.equivalent_strain_rate);
        const Mandel6x6       C = yld.tangent(m, m.strain_rate_deviator, I);
        SymmetricTensor<2, 3> dD;
        dD[0][0] = 0.2, dD[1][1] = 0.5, dD[2][2] = -0.7, dD[0][2] = 0.4;
        dD *= r;
        const double h = 1e-5;
        const auto   p = yld.evaluate(D + h * dD, 0.1, 0.25, true, I);
        const auto   q = yld.evaluate(D - h * dD, 0.1, 0.25, true, I);
        const SymmetricTensor<2, 3> fd =
          (p.deviatoric_stress - q.deviatoric_stress) / (2 * h);
        test::close("team 1: tangent against differences (" + name + ")",
                    (times(C, dD) - fd).norm() / fd.norm(),
                    0,
                    1e-8);
      }
    // Frame R with rate R D R^T: stress R s R^T.
    const Tensor<2, 3> R = rotation(0.7, 0.3);
    const auto         D = rate_of(0.01);
    const auto         a = yld.evaluate(D, 0.1, 0.25, true, I);
    const auto b = yld.evaluate(symmetrize(R * Tensor<2, 3>(D) * transpose(R)),
                                0.1,
                                0.25,
                                true,
                                yld.hill_map(R));
    const auto rotated =
      symmetrize(R * Tensor<2, 3>(a.deviatoric_stress) * transpose(R));
    test::close("team 1: rotated frame and rate give the rotated stress (" +
                  tag + ")",
                (b.deviatoric_stress - rotated).norm() / rotated.norm(),
                0,
                1e-12);
  }
} // namespace

int main()
{
  check_von_mises(parameters::RigidZone::piecewise, "piecewise");
  check_von_mises(parameters::RigidZone::smooth, "smooth");
  check_team1(parameters::RigidZone::piecewise, "piecewise");
  check_team1(parameters::RigidZone::smooth, "smooth");
  return test::result();
}
