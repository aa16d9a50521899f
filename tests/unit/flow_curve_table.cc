// A tabulated flow curve (Material/Flow curve = table): material B's Swift
// curve sampled at 41 strains reproduces it between the points (linear
// interpolation of a concave curve: within 5e-3 of the curve, measured
// 3.0e-3 in the first segment, where it bends most) and on them exactly; each
// extrapolation rule continues the last point as its formula says; the tensile
// strength by Considere's rule from the table is the curve's within 2e-4
// (6.4e-5 measured); the CSV reader takes a header and comments and refuses
// what the law cannot use, naming the entry.
#include <deal.II/base/exceptions.h>

#include <formsolve/material/flow_stress.h>
#include <formsolve/parameters/flow_curve_file.h>
#include <formsolve/parameters/plausibility.h>

#include "check.h"

#include <cmath>
#include <fstream>

using namespace formsolve;
using parameters::FlowExtrapolation;

namespace
{
  /// Whether reading @p text as a flow curve file fails naming the entry.
  bool refused(const std::string &text)
  {
    std::ofstream("bad_flow_curve.csv") << text;
    try
      {
        parameters::read_flow_curve("bad_flow_curve.csv");
      }
    catch (const dealii::ExceptionBase &e)
      {
        return std::string(e.what()).find("Material/Flow curve file") !=
               std::string::npos;
      }
    return false;
  }
} // namespace

int main()
{
  // Material B: 829 (0.002 + eps)^0.2, sampled at 0 and 40 strains from
  // 1e-3 to 1 (geometric).
  parameters::Material swift;
  {
    std::ofstream f("flow_curve_b.csv");
    f << "# material B, Swift sampled\nstrain,stress\n";
    f.precision(17);
    for (unsigned int k = 0; k <= 40; ++k)
      {
        const double e = k == 0 ? 0. : std::pow(10., -3 + 3. * (k - 1) / 39);
        f << e << "," << 829 * std::pow(0.002 + e, 0.2) << "\n";
      }
  }
  parameters::Material table = swift;
  table.flow_curve           = parameters::FlowCurve::table;
  table.flow_curve_file      = "flow_curve_b.csv";
  table.read_flow_curve();
  table.validate();
  test::close("points read", table.flow_curve_points.size(), 41, 0);

  const material::FlowStress exact(swift), tabulated(table);
  double                     worst = 0, at_points = 0;
  for (unsigned int k = 0; k <= 2000; ++k)
    {
      const double e = 1e-4 + k * (1. - 1e-4) / 2000;
      worst          = std::max(worst,
                       std::abs(tabulated.value(e, 1) / exact.value(e, 1) - 1));
    }
  for (const auto &[e, s] : table.flow_curve_points)
    at_points = std::max(at_points, std::abs(tabulated.value(e, 1) - s));
  test::close("between the points: largest relative difference",
              worst,
              0,
              5e-3);
  test::close("at the points (MPa)", at_points, 0, 1e-9);
  // The slope inside a segment is its secant.
  {
    const auto  &p = table.flow_curve_points;
    const double e = 0.5 * (p[20].first + p[21].first);
    const double sl =
      (p[21].second - p[20].second) / (p[21].first - p[20].first);
    test::close("slope inside a segment", tabulated.d_strain(e, 1), sl, 1e-9);
  }

  // Beyond the last point (1, sigma_N).
  const auto  &p  = table.flow_curve_points;
  const double e0 = p[39].first, s0 = p[39].second, e1 = p[40].first,
               s1    = p[40].second;
  const double power = std::log(s1 / s0) / std::log(e1 / e0);
  test::close("power law at eps = 2",
              tabulated.value(2, 1),
              s1 * std::pow(2 / e1, power),
              1e-9);
  test::close("power law: its exponent is Swift's n near eps = 1",
              power,
              0.2 * 1 / (0.002 + 1),
              2e-4);
  for (const auto rule :
       {FlowExtrapolation::last_slope, FlowExtrapolation::constant})
    {
      auto r                = table;
      r.flow_extrapolation  = rule;
      const double expected = rule == FlowExtrapolation::constant
                                ? s1
                                : s1 + (s1 - s0) / (e1 - e0) * (1.5 - e1);
      test::close(rule == FlowExtrapolation::constant ? "constant beyond"
                                                      : "last slope beyond",
                  material::FlowStress(r).value(1.5, 1),
                  expected,
                  1e-9);
    }

  // Considere's tensile strength from the table and from the curve.
  test::close("tensile strength, table / Swift",
              parameters::tensile_strength(table) /
                parameters::tensile_strength(swift),
              1,
              2e-4);

  // The Swift-Voce blend's strength (found on a grid) at its ends is the
  // closed forms' of Swift and Voce.
  {
    parameters::Material voce = swift, blend = swift;
    voce.flow_curve      = parameters::FlowCurve::voce;
    voce.voce_saturation = 330.2;
    voce.voce_amplitude  = 190.0;
    voce.voce_rate       = 12.4;
    blend                = voce;
    blend.flow_curve     = parameters::FlowCurve::swift_voce;
    for (const double alpha : {0., 1.})
      {
        blend.swift_weight = alpha;
        test::close("Swift-Voce tensile strength at alpha = " +
                      std::to_string(alpha),
                    parameters::tensile_strength(blend) /
                      parameters::tensile_strength(alpha == 0 ? voce : swift),
                    1,
                    1e-6);
      }
  }

  // The reader refuses, naming the entry.
  test::close("one point refused", refused("0, 300\n"), 1, 0);
  test::close("falling strain refused",
              refused("0, 300\n0.2, 400\n0.1, 450\n"),
              1,
              0);
  test::close("softening refused",
              refused("0, 300\n0.2, 400\n0.4, 390\n"),
              1,
              0);
  test::close("zero stress refused", refused("0, 0\n0.2, 400\n"), 1, 0);
  test::close("negative strain refused",
              refused("-0.1, 300\n0.2, 400\n"),
              1,
              0);
  test::close("words after a point refused", refused("0, 300\nx, y\n"), 1, 0);
  test::close(
    "a missing file refused",
    [] {
      try
        {
          parameters::read_flow_curve("no_such_flow_curve.csv");
        }
      catch (const dealii::ExceptionBase &)
        {
          return true;
        }
      return false;
    }(),
    1,
    0);
  return test::result();
}
