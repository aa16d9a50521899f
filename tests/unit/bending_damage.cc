// Oyane's integral in plane-strain pure bending of a rigid-perfectly-plastic
// strip (bending_strip.h), one step of the history update after the solve:
// the local I at every point and the through-thickness column average
// against their closed forms (2 %), with von Mises and with Hill's normal
// anisotropy (r = 2), for both sources of the mean stress (Material/Fracture
// mean stress), on Q2 elements, whose space holds the exact flow (v_z is
// quadratic in x and z; one planform refinement suffices). Q1 cannot bend
// without parasitic shear and a thickness rate constant per layer: its points
// are off by about 8 % (printed), its column average is checked.
//
// Closed form (doc/theory.md, section 11b): with the curvature rate
// kappa = 2 omega/L, the fibre zeta = z - t/2 stretches at kappa zeta;
// plane strain with sigma_z = 0 and Hill's normal anisotropy r gives
// sigma_m/sigma_bar = sign(zeta) sqrt(1 + 2r)/3 and
// d eps_bar = (1 + r)/sqrt(1 + 2r) |d eps_x|, so over a step dt
//   I(zeta) = (sign(zeta) sqrt(1 + 2r)/3 + a) (1 + r)/sqrt(1 + 2r) kappa
//             |zeta| dt / b,
// and its average through the thickness keeps only a:
//   I_avg = a (1 + r)/sqrt(1 + 2r) kappa dt t / (4 b).
// The mean stress jumps at the neutral axis; an element pressure holds it
// exactly per layer, the projection smears it over the layers next to the
// axis (inner-layer points off by 2.6 % with 4 layers; with 2 layers
// the outer fibre's I by +5.5 %: printed).
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/material/damage.h>
#include <formsolve/postprocess/through_thickness.h>
#include <formsolve/state/history_update.h>

#include "bending_strip.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double sigma0 = 100, a = 0.3, b = 0.2, dt = 1e-3, step = 10;

  parameters::Material strip_material(const double                 r,
                                      const parameters::MeanStress mean)
  {
    parameters::Material m;
    m.strength_coefficient = sigma0;
    m.hardening_exponent   = 0;
    m.limiting_strain_rate = 1e-7;
    m.oyane_a              = a;
    m.oyane_b              = b;
    m.mean_stress          = mean;
    if (r != 1)
      {
        m.anisotropy.criterion = parameters::YieldCriterion::hill48;
        m.anisotropy.r_values  = {r};
        m.anisotropy.damage_normalisation =
          parameters::DamageNormalisation::rolling_direction;
      }
    return m;
  }

  struct Errors
  {
    double outer = 0, inner = 0; // largest |I - exact| / I_outer_fibre
    double largest_local = 0, largest_exact = 0;
  };

  /// Point values of I against the closed form, in the layers |zeta| > t/4
  /// (outer) and below (inner).
  Errors local_errors(const test::BendingStrip &strip, const double r)
  {
    const auto  &s     = strip.state;
    const double t     = strip.size.t;
    const double kappa = 2 * strip.size.omega / strip.size.L;
    const double k     = (1 + r) / std::sqrt(1 + 2 * r);
    const auto   exact = [&](const double zeta) {
      const double sign = zeta > 0 ? 1. : -1.;
      return (sign * std::sqrt(1 + 2 * r) / 3 + a) * k * kappa *
             std::abs(zeta) * step / b;
    };
    const double scale = exact(t / 2);
    FEValues<3>  fv(s.reference_mapping,
                   s.fe,
                   s.history_rule,
                   update_quadrature_points);
    Errors       e;
    for (const auto &cell : s.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          const auto h = s.history.get_data(cell);
          for (unsigned int q = 0; q < h.size(); ++q)
            {
              const double zeta = fv.quadrature_point(q)[2] - t / 2;
              const double err  = std::abs(h[q]->oyane - exact(zeta)) / scale;
              (std::abs(zeta) > t / 4 ? e.outer : e.inner) =
                std::max(std::abs(zeta) > t / 4 ? e.outer : e.inner, err);
              e.largest_local = std::max(e.largest_local, h[q]->oyane);
              e.largest_exact = std::max(e.largest_exact, exact(zeta));
            }
        }
    const MPI_Comm comm = MPI_COMM_WORLD;
    return {Utilities::MPI::max(e.outer, comm),
            Utilities::MPI::max(e.inner, comm),
            Utilities::MPI::max(e.largest_local, comm),
            Utilities::MPI::max(e.largest_exact, comm)};
  }

  void check(const double                 r,
             const parameters::MeanStress mean,
             const unsigned int           degree,
             const unsigned int           layers)
  {
    const std::string name =
      std::string(r == 1 ? "von Mises" : "Hill r = 2") + ", " +
      (mean == parameters::MeanStress::projected ? "projected"
                                                 : "cell pressure") +
      ", Q" + std::to_string(degree) + ", " + std::to_string(layers) +
      " layers";
    test::BendingStrip strip({},
                             {degree, layers, degree == 2 ? 1u : 2u},
                             strip_material(r, mean),
                             dt);
    strip.solve_flow();
    const material::DamageCriteria damage(strip.prm.material);
    const state::HistoryUpdate<3>  update(strip.material,
                                         strip.state.kinematics,
                                         strip.state.reference_mapping,
                                         degree,
                                         &damage);
    update.advance(strip.state.dof_handler,
                   strip.state.reference_mapping,
                   strip.state.velocity_ghost,
                   step,
                   strip.state.history);
    const Errors                           e = local_errors(strip, r);
    postprocess::ThroughThicknessDamage<3> measure;
    const double                           column =
      measure.measure(strip.state, damage, false).oyane.value;
    const double kappa        = 2 * strip.size.omega / strip.size.L;
    const double column_exact = a * (1 + r) / std::sqrt(1 + 2 * r) * kappa *
                                step * strip.size.t / (4 * b);
    std::cout << name << ": largest local I " << e.largest_local
              << " (closed form at the outermost point " << e.largest_exact
              << "), point errors / I(t/2): outer layers " << e.outer
              << ", inner layers " << e.inner << "; column average " << column
              << " (closed form " << column_exact << ")\n";
    test::close(name + ": column average / closed form",
                column / column_exact,
                1,
                0.02);
    // Q1 points, and the projection's across two layers (the axis's jump
    // smeared onto the outer fibre): printed, not the closed form.
    if (degree == 1 ||
        (mean == parameters::MeanStress::projected && layers < 4))
      return;
    test::close(name + ": largest local I / closed form",
                e.largest_local / e.largest_exact,
                1,
                0.02);
    test::close(name + ": outer-layer points", e.outer, 0, 0.02);
    if (mean == parameters::MeanStress::cell_pressure)
      test::close(name + ": inner-layer points", e.inner, 0, 0.02);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using parameters::MeanStress;
  check(1., MeanStress::cell_pressure, 2, 4);
  check(1., MeanStress::projected, 2, 4);
  check(2., MeanStress::cell_pressure, 2, 4);
  check(1., MeanStress::cell_pressure, 2, 2);
  check(1., MeanStress::projected, 2, 2);
  check(1., MeanStress::cell_pressure, 1, 4);
  return test::result();
}
