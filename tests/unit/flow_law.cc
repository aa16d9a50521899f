// The flow law at a point (material/rigid_viscoplastic.cc), both rigid-zone
// laws (Material/Rigid zone), with and without rate sensitivity:
// - smooth: the equivalent stress equals s r/sqrt(r^2 + r_c^2) (eq. 3a) and
//   tends to s well above r_c and to s r/r_c well below it;
// - piecewise: s above r_c, s r/r_c below, continuous at r_c;
// - Newton's tangent 2 mu P_dev + beta D' (x) D' equals the central finite
//   difference of the deviatoric stress (hardening through eps_n + dt r
//   included) to 1e-5 relative, on both sides of r_c and across it for the
//   smooth law.
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/parameters/material.h>

#include "check.h"
#include "point_rate.h"

#include <cmath>
#include <string>

using namespace dealii;
using namespace formsolve;

namespace
{
  using test::rate_of;

  double norm(const SymmetricTensor<2, 3> &t)
  {
    return std::sqrt(t * t);
  }

  void check_tangent(const material::RigidViscoplastic &law,
                     const std::string                 &name,
                     const double                       r,
                     const double                       strain,
                     const double                       dt)
  {
    const auto D = rate_of(r);
    const auto m = law.evaluate(D, strain, dt, true);
    // A direction with a component along D' and one across it.
    SymmetricTensor<2, 3> dD;
    dD[0][0] = 0.2;
    dD[1][1] = 0.5;
    dD[2][2] = -0.7;
    dD[0][2] = 0.4;
    dD *= r;
    const double                h  = 1e-5;
    const auto                  sp = law.evaluate(D + h * dD, strain, dt, true);
    const auto                  sm = law.evaluate(D - h * dD, strain, dt, true);
    const SymmetricTensor<2, 3> fd =
      (sp.deviatoric_stress - sm.deviatoric_stress) / (2 * h);
    const SymmetricTensor<2, 3> e = deviator(D);
    const SymmetricTensor<2, 3> tangent =
      2 * m.viscosity * deviator(dD) + m.beta * (e * dD) * e;
    test::close(name + ", r = " + std::to_string(r) +
                  ": tangent against finite differences",
                norm(tangent - fd) / norm(fd),
                0,
                1e-5);
  }
} // namespace

int main()
{
  parameters::Material p;
  p.limiting_strain_rate = 1e-4;
  const double rc = p.limiting_strain_rate, strain = 0.1, dt = 0.25;

  for (const double m : {0., 0.02})
    {
      p.rate_sensitivity    = m;
      const std::string tag = "m = " + std::to_string(m);
      // Smooth law.
      p.rigid_zone = parameters::RigidZone::smooth;
      const material::RigidViscoplastic smooth(p);
      const material::FlowStress        flow(p);
      for (const double r : {1e-6, 3e-5, 1e-4, 3e-4, 1e-2, 1.})
        {
          const double rho = std::sqrt(r * r + rc * rc);
          const auto   out = smooth.evaluate(rate_of(r), strain, dt, false);
          test::close("smooth, " + tag + ", r = " + std::to_string(r) +
                        ": s_bar = s r/sqrt(r^2 + r_c^2)",
                      out.flow_stress /
                        (flow.value(strain + dt * r, rho) * r / rho),
                      1,
                      1e-12);
          check_tangent(smooth, "smooth, " + tag, r, strain, dt);
        }
      // Its limits: the flow stress well above r_c, linear viscous below.
      const auto high = smooth.evaluate(rate_of(1.), strain, dt, false);
      test::close("smooth, " + tag + ": s_bar/s at r = 1e4 r_c",
                  high.flow_stress / flow.value(strain + dt, 1.),
                  1,
                  1e-8);
      const auto low = smooth.evaluate(rate_of(1e-7), strain, dt, false);
      test::close("smooth, " + tag +
                    ": viscosity at r = 1e-3 r_c over s/(3 r_c)",
                  low.viscosity / (flow.value(strain, rc) / (3 * rc)),
                  1,
                  2e-6);

      // Piecewise law: continuous at r_c, tangent exact on each side.
      p.rigid_zone = parameters::RigidZone::piecewise;
      const material::RigidViscoplastic piecewise(p);
      const double                      below =
        piecewise.evaluate(rate_of(rc * (1 - 1e-9)), strain, dt, false)
          .flow_stress;
      const double above =
        piecewise.evaluate(rate_of(rc * (1 + 1e-9)), strain, dt, false)
          .flow_stress;
      test::close("piecewise, " + tag + ": continuous at r_c",
                  below / above,
                  1,
                  1e-8);
      for (const double r : {3e-5, 1e-2, 1.})
        check_tangent(piecewise, "piecewise, " + tag, r, strain, dt);
    }

  // Voce's curve sigma = A - B exp(-C eps) (rate/rate0)^m: its closed form,
  // its slope, and the point law's tangent through it.
  p.flow_curve      = parameters::FlowCurve::voce;
  p.voce_saturation = 330.2;
  p.voce_amplitude  = 190.0;
  p.voce_rate       = 12.4;
  p.rigid_zone      = parameters::RigidZone::smooth;
  p.validate();
  const material::FlowStress voce(p);
  const double               factor = std::pow(2., p.rate_sensitivity);
  for (const double e : {0., 0.1, 0.5})
    {
      test::close("Voce: sigma(" + std::to_string(e) + ")",
                  voce.value(e, 2.),
                  (330.2 - 190.0 * std::exp(-12.4 * e)) * factor,
                  1e-9);
      test::close("Voce: slope at " + std::to_string(e),
                  voce.d_strain(e, 2.),
                  190.0 * 12.4 * std::exp(-12.4 * e) * factor,
                  1e-9);
    }
  const material::RigidViscoplastic voce_law(p);
  for (const double r : {3e-5, 1e-2, 1.})
    check_tangent(voce_law, "Voce", r, strain, dt);

  // The Swift-Voce blend alpha Swift + (1 - alpha) Voce: its closed form,
  // its slope, the ends alpha = 1 (Swift) and 0 (Voce), the tangent.
  p.flow_curve   = parameters::FlowCurve::swift_voce;
  p.swift_weight = 0.3;
  p.validate();
  const double K = p.strength_coefficient, n = p.hardening_exponent,
               e0 = p.prestrain;
  const material::FlowStress blend(p);
  for (const double e : {0., 0.1, 0.5})
    {
      const double swift  = K * std::pow(e0 + e, n),
                   voce_h = 330.2 - 190.0 * std::exp(-12.4 * e);
      test::close("Swift-Voce: sigma(" + std::to_string(e) + ")",
                  blend.value(e, 2.),
                  (0.3 * swift + 0.7 * voce_h) * factor,
                  1e-9);
      test::close("Swift-Voce: slope at " + std::to_string(e),
                  blend.d_strain(e, 2.),
                  (0.3 * n * swift / (e0 + e) +
                   0.7 * 190.0 * 12.4 * std::exp(-12.4 * e)) *
                    factor,
                  1e-9);
    }
  for (const double alpha : {0., 1.})
    {
      auto q         = p;
      q.swift_weight = alpha;
      auto r         = p;
      r.flow_curve   = alpha == 0. ? parameters::FlowCurve::voce
                                   : parameters::FlowCurve::swift;
      test::close("Swift-Voce at alpha = " + std::to_string(alpha),
                  material::FlowStress(q).value(0.3, 2.),
                  material::FlowStress(r).value(0.3, 2.),
                  1e-9);
    }
  const material::RigidViscoplastic blend_law(p);
  for (const double r : {3e-5, 1e-2, 1.})
    check_tangent(blend_law, "Swift-Voce", r, strain, dt);

  // Hockett-Sherby A - B exp(-C eps^p): closed form and slope above
  // eps_c = 1e-4, the chord below (continuous at eps_c), p = 1 is Voce,
  // and the tangent.
  p.flow_curve              = parameters::FlowCurve::hockett_sherby;
  p.hockett_sherby_exponent = 0.6;
  p.validate();
  const material::FlowStress hs(p);
  for (const double e : {1e-3, 0.1, 0.5})
    {
      const double x = std::exp(-12.4 * std::pow(e, 0.6));
      test::close("Hockett-Sherby: sigma(" + std::to_string(e) + ")",
                  hs.value(e, 2.),
                  (330.2 - 190.0 * x) * factor,
                  1e-9);
      test::close("Hockett-Sherby: slope at " + std::to_string(e),
                  hs.d_strain(e, 2.),
                  190.0 * 12.4 * 0.6 * std::pow(e, -0.4) * x * factor,
                  1e-9);
    }
  const double at_c = 330.2 - 190.0 * std::exp(-12.4 * std::pow(1e-4, 0.6));
  test::close("Hockett-Sherby: the chord's slope below 1e-4",
              hs.d_strain(5e-5, 2.),
              (at_c - (330.2 - 190.0)) / 1e-4 * factor,
              1e-9);
  test::close("Hockett-Sherby: continuous at 1e-4",
              hs.value(1e-4 * (1 - 1e-12), 2.) / hs.value(1e-4, 2.),
              1,
              1e-10);
  auto voce_p                    = p;
  voce_p.hockett_sherby_exponent = 1;
  test::close("Hockett-Sherby at p = 1 is Voce",
              material::FlowStress(voce_p).value(0.3, 2.),
              voce.value(0.3, 2.),
              1e-12);
  const material::RigidViscoplastic hs_law(p);
  for (const double r : {3e-5, 1e-2, 1.})
    check_tangent(hs_law, "Hockett-Sherby", r, strain, dt);
  return test::result();
}
