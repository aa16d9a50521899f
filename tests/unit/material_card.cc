// A material card of prm/materials (the argument), read through the input
// machinery as a run reads it, in a free block pulled along x (full 3-D
// model, Newton-solved steps through the assembler):
// - along RD, step by step to a strain of 0.2 with the geometry updated:
//   the end force over the current section (volume over length) is the
//   card's flow curve at the point's implicitly updated strain eps_n + dt
//   rate, evaluated here from the card's entries (Swift, Voce, Swift-Voce,
//   Hockett-Sherby in closed form, a table by linear interpolation), times
//   (rate/rate0)^m and the smooth rigid zone's rate/sqrt(rate^2 +
//   cutoff^2), to 1e-8 (1e-11 measured); the strain stays within 1e-3 of
//   ln(L/L0) (2.3e-4: the first-order update);
// - at 0, 45 and 90 degrees to RD: the block's r-value and sigma_theta /
//   sigma_0 are those of the card's criterion (1 for von Mises; Hill48 from
//   its r-values or stress ratios; Yld2004-18p from its coefficients or its
//   fit), to 1e-8 relative (they agree to the 12 digits printed).
// A card whose entries are read into the wrong member, a curve or criterion
// the law does not evaluate as the card says, fails here.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <formsolve/material/yld2004.h>
#include <formsolve/parameters/command_line.h>
#include <formsolve/parameters/parameters.h>

#include "block_tension.h"
#include "check.h"

#include <algorithm>
#include <cmath>

using namespace dealii;
using namespace formsolve;

namespace
{
  /// The card's flow curve at @p e, from its entries (doc/theory.md, eqs.
  /// 2, 2v, 2sv, 2hs, 2t within the table).
  double curve(const parameters::Material &m, const double e)
  {
    using parameters::FlowCurve;
    const double swift =
      m.strength_coefficient * std::pow(m.prestrain + e, m.hardening_exponent);
    const double voce =
      m.voce_saturation - m.voce_amplitude * std::exp(-m.voce_rate * e);
    switch (m.flow_curve)
      {
        case FlowCurve::swift:
          return swift;
        case FlowCurve::voce:
          return voce;
        case FlowCurve::swift_voce:
          return m.swift_weight * swift + (1 - m.swift_weight) * voce;
        case FlowCurve::hockett_sherby:
          {
            // The chord from 0 to 1e-4 (eq. 2hs).
            const auto hs = [&m](const double x) {
              return m.voce_saturation -
                     m.voce_amplitude *
                       std::exp(-m.voce_rate *
                                std::pow(x, m.hockett_sherby_exponent));
            };
            return e >= 1e-4 ? hs(e) : hs(0) + (hs(1e-4) - hs(0)) * e / 1e-4;
          }
        case FlowCurve::table:
          {
            const auto &p = m.flow_curve_points;
            auto        k = std::upper_bound(p.begin(),
                                      p.end(),
                                      e,
                                      [](double x, const auto &q) {
                                        return x < q.first;
                                      });
            AssertThrow(k != p.begin() && k != p.end(),
                        ExcMessage("strain outside the card's table"));
            const auto &a = *(k - 1), &b = *k;
            return a.second +
                   (b.second - a.second) * (e - a.first) / (b.first - a.first);
          }
      }
    return 0;
  }

  double rate_factor(const parameters::Material &m, const double rate)
  {
    const double smooth =
      m.rigid_zone == parameters::RigidZone::smooth
        ? rate / std::sqrt(rate * rate +
                           m.limiting_strain_rate * m.limiting_strain_rate)
        : 1.;
    return std::pow(rate / m.reference_strain_rate, m.rate_sensitivity) *
           smooth;
  }

  parameters::Run read_card(const std::string &card)
  {
    ParameterHandler         handler;
    parameters::Run          run;
    parameters::Declarations declarations(handler);
    parameters::CommandLine  cl;
    run.declare(declarations);
    cl.input_file = card;
    parameters::read_input(declarations, run.tools, cl);
    run.complete();
    return run;
  }

  /// Pulled along RD in steps of V dt: the force over the section against
  /// the curve at the point's strain eps_old + dt V/L (the law's implicit
  /// update), and that strain against ln(L/L0).
  void check_flow_curve(const parameters::Run &prm)
  {
    using test::L, test::W, test::T, test::V, test::dt;
    test::BlockRun run(prm);
    auto          &state = run.state;
    test::Tension  tension(state, run.assembler, false);
    const auto     point = [&state]() {
      return state.history.get_data(state.dof_handler.begin_active())[0];
    };
    double length = L, worst = 0, drift = 0;
    while (point()->strain < 0.2)
      {
        tension.solve_flow();
        // The penalty leaves a small volume rate (tr D ~ 1e-3 of D_xx):
        // the section from the current volume, and the point's own
        // equivalent (deviatoric) rate.
        const double area =
          GridTools::volume(state.tria, *state.mapping) / length;
        const double stress = tension.end_force() / area;
        const double before = point()->strain;
        state.advance(dt, run.update);
        const double rate     = point()->strain_rate;
        const double expected = curve(prm.material, before + dt * rate) *
                                rate_factor(prm.material, rate);
        worst = std::max(worst, std::abs(stress / expected - 1));
        length += V * dt;
        drift =
          std::max(drift, std::abs(point()->strain - std::log(length / L)));
      }
    test::close("RD flow curve: largest relative error to a strain of 0.2",
                worst,
                0,
                1e-8);
    test::close("... the point's strain against ln(L/L0)", drift, 0, 1e-3);
  }

  void check_directions(const parameters::Run &prm)
  {
    const auto &a    = prm.material.anisotropy;
    const auto  hill = material::Hill48::from_parameters(a);
    const auto  yld  = a.non_quadratic()
                         ? std::optional(material::Yld2004::from_parameters(a))
                         : std::nullopt;
    for (const double theta : {0., 45., 90.})
      {
        const double t = theta * M_PI / 180;
        const double r = yld ? yld->r_value(t) : hill.r_value(t);
        const double s = yld ? yld->stress_ratio(t) : hill.stress_ratio(t);
        const test::Measured m  = test::pull(prm, theta, false);
        const std::string    at = " at " + std::to_string(int(theta)) + " deg";
        test::close("r-value" + at, m.r_value, r, 1e-8 * r);
        test::close("sigma_theta/sigma_0" + at,
                    m.stress_over_flow_stress,
                    s,
                    1e-8 * s);
      }
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  AssertThrow(argc == 2, ExcMessage("usage: test_material_card <card.prm>"));
  std::cout.precision(12);
  parameters::Run prm = test::block(read_card(argv[1]));
  // A fitted set from 4 starts, for the Debug build's time: the block
  // checks the card's path to the law, not the fit's quality.
  auto &fit  = prm.material.anisotropy.fit;
  fit.starts = std::min(fit.starts, 4u);
  std::cout << "card " << argv[1] << ": " << prm.material.anisotropy.describe()
            << "\n";
  check_flow_curve(prm);
  check_directions(prm);
  return test::result();
}
