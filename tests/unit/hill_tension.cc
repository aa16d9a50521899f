// Homogeneous tension of a Hill48 sheet (a free block, full 3-D model), one
// step solved by Newton's method through the assembler: the ends move apart
// along x, RD at the angle theta to x.
// - Uniaxial tension at 0, 45 and 90 degrees to RD, with Hill from r0, r45,
//   r90 and from yield stress ratios: the measured r-value (deviatoric width
//   over thickness strain rate) equals Hill's r(theta), and the end force over
//   the cross-section, divided by the flow stress at the point, equals Hill's
//   sigma_theta/sigma_0, each within 0.5 % (they agree to the 6 digits
//   printed).
// - Plane-strain tension along RD (sides held): sigma_1/sigma_bar equals
//   1/sqrt(G + F H/(F + H)) within 0.5 %.
// - The calibration chain: homogeneous uniaxial and plane-strain tension of
//   the reference materials A, B, C with their r reach Oyane's I = 1 at the
//   tension-test fracture strains within 2 % (constants converted from
//   Hill's normal-anisotropy normalisation).
// - Yld2004-18p (the earing reference's team 1 set): the block's r and
//   sigma_theta/sigma_0 at 0, 45, 90 degrees are the criterion's (1e-4)
//   and the measured ones it was fitted to (0.015; the set's own fit
//   misses them by up to 0.011).
// A wrong convention (F and G swapped, a shear factor), a frame that ignores
// the rolling direction or a wrong stress map fails here.
#include <deal.II/base/mpi.h>

#include <formsolve/material/yld2004.h>

#include "block_tension.h"
#include "check.h"

#include <cmath>

using namespace dealii;
using namespace formsolve;
using test::Measured;
using test::pull;

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  parameters::Run                  prm = test::block(parameters::Run());
  prm.material.strength_coefficient    = 500;
  prm.material.hardening_exponent      = 0.2;
  auto &a                              = prm.material.anisotropy;
  a.criterion                          = parameters::YieldCriterion::hill48;

  for (const auto calibration : {parameters::HillCalibration::r_values,
                                 parameters::HillCalibration::yield_stresses})
    {
      a.calibration         = calibration;
      a.r_values            = {2.1, 1.6, 2.7};
      a.yield_stress_ratios = {1.03, 0.97, 1.15};
      const auto hill       = material::Hill48::from_parameters(a);
      for (const double theta : {0., 45., 90.})
        {
          const Measured    m = pull(prm, theta, false);
          const double      t = theta * M_PI / 180;
          const std::string at =
            " at " + std::to_string(int(theta)) + " deg" +
            (calibration == parameters::HillCalibration::r_values
               ? " (r-values)"
               : " (yield stresses)");
          test::close("r-value" + at,
                      m.r_value,
                      hill.r_value(t),
                      5e-3 * hill.r_value(t));
          test::close("sigma_theta/sigma_0" + at,
                      m.stress_over_flow_stress,
                      hill.stress_ratio(t),
                      5e-3 * hill.stress_ratio(t));
          if (calibration == parameters::HillCalibration::r_values)
            test::close("Hill's r" + at,
                        hill.r_value(t),
                        a.r_values[theta == 0    ? 0
                                   : theta == 45 ? 1
                                                 : 2],
                        1e-12);
          else if (theta > 0)
            test::close("Hill's stress ratio" + at,
                        hill.stress_ratio(t),
                        a.yield_stress_ratios[theta == 45 ? 0 : 1],
                        1e-12);
        }
      const Measured ps = pull(prm, 0, true);
      const double   plane =
        1 / std::sqrt(hill.G + hill.F * hill.H / (hill.F + hill.H));
      test::close("plane strain sigma_1/sigma_bar",
                  ps.stress_over_flow_stress,
                  plane,
                  5e-3 * plane);
    }

  // Yld2004-18p (the earing reference's team 1 set, a = 8): the block's
  // r-value and stress ratio at 0, 45, 90 degrees are the criterion's
  // (1e-4; they agree to the 6 digits printed), and within 0.015 of the
  // measured ones it was fitted to (r 0.526, 0.253, 0.601; sigma/sigma0 1,
  // 0.908, 0.983): the set's own fit misses them by up to 0.011 (r45) and 0.010
  // (sigma45).
  a.criterion      = parameters::YieldCriterion::yld2004_18p;
  a.yield_exponent = 8;
  a.yld_c1         = {1.1998, 1.2289, 0.1315, 0.8081, 1.1386, 0.2870, 1.3739};
  a.yld_c2         = {1.1510, -0.2576, 0.4873, 0.9934, 0.9110, 0.7965, 0.2679};
  const auto   yld = material::Yld2004::from_parameters(a);
  const double r_measured[] = {0.526, 0.253, 0.601},
               s_measured[] = {1, 0.908, 0.983};
  for (const unsigned int k : {0u, 1u, 2u})
    {
      const double      theta = 45. * k, t = theta * M_PI / 180;
      const Measured    m  = pull(prm, theta, false);
      const std::string at = " at " + std::to_string(int(theta)) + " deg";
      test::close("Yld2004-18p r-value" + at,
                  m.r_value,
                  yld.r_value(t),
                  1e-4 * yld.r_value(t));
      test::close("Yld2004-18p sigma_theta/sigma_0" + at,
                  m.stress_over_flow_stress,
                  yld.stress_ratio(t),
                  1e-4 * yld.stress_ratio(t));
      test::close("... the measured r" + at, m.r_value, r_measured[k], 0.015);
      test::close("... the measured stress ratio" + at,
                  m.stress_over_flow_stress,
                  s_measured[k],
                  0.015);
    }
  a.criterion = parameters::YieldCriterion::hill48;

  // The calibration chain of the reference materials A, B, C (constants in
  // Hill's normal-anisotropy normalisation, converted by formsolve): I
  // reaches 1 at the tension-test fracture strains eps1f, uniaxial and in
  // plane strain, within 2 % (the deformation is proportional, so I grows
  // linearly with the axial strain).
  struct Reference
  {
    const char *name;
    double      K, n, r, a, b, uniaxial, plane;
  };
  for (const Reference &m :
       {Reference{"A", 858, 0.03, 0.87, -0.132, 0.063, 0.303, 0.130},
        Reference{"B", 829, 0.20, 0.81, 0.020, 0.217, 0.595, 0.336},
        Reference{"C", 1020, 0.14, 0.91, -0.098, 0.152, 0.634, 0.285}})
    {
      prm.material.strength_coefficient = m.K;
      prm.material.hardening_exponent   = m.n;
      prm.material.oyane_a              = m.a;
      prm.material.oyane_b              = m.b;
      a.calibration                     = parameters::HillCalibration::r_values;
      a.r_values                        = {m.r};
      for (const bool plane : {false, true})
        test::close(std::string("I at eps1f, material ") + m.name +
                      (plane ? ", plane strain" : ", uniaxial"),
                    pull(prm, 0, plane).oyane_per_axial_strain *
                      (plane ? m.plane : m.uniaxial),
                    1,
                    0.02);
    }
  return test::result();
}
