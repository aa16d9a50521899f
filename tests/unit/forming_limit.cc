// The forming limit curve (material/forming_limit.cc): Keeler-Brazier from
// n and t0 (FLC0 = (23.3 + 14.13 t) n / 0.21 % engineering; constant
// thinning on the left, slope 0.6 in engineering strains on the right),
// and Material/Forming limit table (linear between its points, constant
// beyond its ends); the safety zones against the curve and its margin.
#include <formsolve/material/forming_limit.h>

#include "check.h"

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

using formsolve::material::FormingLimit;
using formsolve::material::SafetyZone;

int main()
{
  formsolve::parameters::Material p;
  p.hardening_exponent = 0.2;
  p.safety_margin      = 0.1;
  {
    const FormingLimit flc(p, 0.78);
    const double       e0 = (23.3 + 14.13 * 0.78) * 0.2 / 0.21 / 100.;
    test::close("Keeler-Brazier FLC0 (true)",
                flc.plane_strain_limit(),
                std::log1p(e0),
                1e-14);
    test::close("left: constant thinning, major + minor = FLC0",
                flc.major(-0.2) - 0.2,
                std::log1p(e0),
                1e-14);
    test::close("right: slope 0.6 in engineering strains",
                flc.major(std::log1p(0.1)),
                std::log1p(e0 + 0.06),
                1e-14);
    test::close("right: flat beyond 20 % minor engineering strain",
                flc.major(std::log1p(0.3)),
                std::log1p(e0 + 0.12),
                1e-14);
    p.hardening_exponent = 0.3;
    test::close("n capped at 0.21",
                FormingLimit(p, 0.78).plane_strain_limit(),
                std::log1p((23.3 + 14.13 * 0.78) / 100.),
                1e-14);
    p.hardening_exponent = 0.2;
  }
  p.forming_limit_table = {{-0.2, 0.5}, {0., 0.3}, {0.2, 0.4}};
  const FormingLimit table(p, 0.78);
  test::close("table: the source says so",
              table.source().find("table") == 0,
              1,
              0);
  test::close("table: a point", table.major(0.), 0.3, 1e-15);
  test::close("table: linear between points", table.major(-0.05), 0.35, 1e-14);
  test::close("table: linear between points", table.major(0.1), 0.35, 1e-14);
  test::close("table: constant below its first point",
              table.major(-0.5),
              0.5,
              0);
  test::close("table: constant beyond its last point",
              table.major(0.5),
              0.4,
              0);
  // The zones against the table's curve (FLC(0) = 0.3, margin 10 %) and
  // the default thresholds: severe thinning above 30 %, i.e. major + minor
  // > -ln(0.7) = 0.357; insufficient stretch below 2 % major strain.
  const auto zone = [&](double minor, double major, double damage) {
    return static_cast<int>(table.zone(minor, major, damage));
  };
  const std::vector<
    std::tuple<const char *, double, double, double, SafetyZone>>
    points = {
      {"safe", 0.05, 0.1, 0, SafetyZone::safe},
      {"insufficient stretch below 2 % major",
       0.005,
       0.015,
       0,
       SafetyZone::insufficient_stretch},
      {"wrinkling tendency: major + minor < 0",
       -0.1,
       0.05,
       0,
       SafetyZone::wrinkling},
      {"compression: both negative", -0.1, -0.02, 0, SafetyZone::compression},
      {"severe thinning: 1 - exp(-0.4) > 0.3 below the margin",
       0.15,
       0.25,
       0,
       SafetyZone::severe_thinning},
      {"risk of crack within 10 % below the curve",
       0.,
       0.28,
       0,
       SafetyZone::risk_of_crack},
      {"crack at the curve", 0., 0.3, 0, SafetyZone::crack},
      {"crack above the curve", -0.2, 0.51, 0, SafetyZone::crack},
      {"fracture once damage reaches 1", 0., 0.1, 1., SafetyZone::fracture}};
  for (const auto &[what, minor, major, damage, expected] : points)
    test::close(std::string("zone: ") + what,
                zone(minor, major, damage),
                int(expected),
                0);
  test::close("zone names as column keys",
              formsolve::material::zone_key(SafetyZone::risk_of_crack) ==
                "risk_of_crack",
              1,
              0);
  return test::result();
}
