// Equivalent draw beads: the bead model (beads/bead_model.cc) against its
// closed forms: the wrap angle is 0 at no penetration, pi/2 at R_b + R_s + t
// and in between the angle of the sheet's line tangent to both arcs;
// without friction the restraining force is the six bends' M_p / rho at
// any wrap and the opening force that tension times sin(theta) at both
// sides of the bead; friction multiplies each arc's tension by exp(mu
// theta), so that the force grows with the penetration. The line's points
// (beads/bead_line.cc): their weights sum to the line's length (cut exactly at
// symmetry planes and a slice's faces), their normals are unit and across the
// line; a 2-D bead's point has the ring or the width as its length.
#include <formsolve/beads/bead_line.h>
#include <formsolve/beads/bead_model.h>

#include "check.h"

#include <cmath>

using namespace formsolve;

namespace
{
  template <int dim>
  double total(const std::vector<beads::BeadPoint<dim>> &points)
  {
    double sum = 0;
    for (const auto &p : points)
      sum += p.weight;
    return sum;
  }

  void bead_model()
  {
    const beads::BeadGeometry g{4, 3, 0};
    const double              t = 0.8, rs = 3.4, rb = 4.4, sigma = 400;
    test::close("no penetration: no wrap",
                beads::wrap_angle(g, 0, t),
                0,
                1e-15);
    test::close("penetration R_b + R_s + t: a quarter turn",
                beads::wrap_angle(g, rs + rb, t),
                M_PI / 2,
                1e-12);
    // At p = 3 mm the sheet leaves the shoulder's arc (centre (0, -rs)) at
    // angle theta downwards; the bead's arc (centre (rs + rb, rb - 3)) must
    // touch that line from the other side, rb away.
    const double theta = beads::wrap_angle(g, 3, t);
    const double px = rs * std::sin(theta), pz = -rs + rs * std::cos(theta);
    const double dx = std::cos(theta), dz = -std::sin(theta);
    const double cx = rs + rb - px, cz = rb - 3 - pz;
    test::close("the sheet's line is tangent to the bead",
                dx * cz - dz * cx,
                rb,
                1e-12);
    const auto   f  = beads::bead_forces(g, 3, t, sigma);
    const double mp = sigma * t * t / 4;
    test::close("frictionless: six bends of M_p / rho",
                f.restraining,
                4 * mp / rs + 2 * mp / rb,
                1e-12);
    test::close("frictionless opening: 2 (2 M_p/rho_s + M_p/rho_b) sin theta",
                f.opening,
                2 * (2 * mp / rs + mp / rb) * std::sin(theta),
                1e-12);
    const beads::BeadGeometry rough{4, 3, 0.1};
    const auto                fr = beads::bead_forces(rough, 3, t, sigma);
    const double e = std::exp(0.1 * theta), ds = mp / rs, db = mp / rb;
    test::close("friction: each arc multiplies the tension by exp(mu theta)",
                fr.restraining,
                ((ds * e + ds + db) * e * e + db + ds) * e + ds,
                1e-12);
    test::close("friction adds", fr.restraining > f.restraining, 1, 0);
    test::close("deeper, more friction force",
                beads::bead_forces(rough, 4, t, sigma).restraining >
                  fr.restraining,
                1,
                0);
    test::close("frictionless, deeper: the same six bends",
                beads::bead_forces(g, 4, t, sigma).restraining,
                f.restraining,
                1e-12);
    test::close("deeper, more opening force",
                beads::bead_forces(g, 4, t, sigma).opening > f.opening,
                1,
                0);
  }

  void lines()
  {
    parameters::DrawBead bead;
    bead.line = {{0, 0}, {10, 0}, {10, 5}};
    const model::Kinematics<3> k3(false);
    auto p = beads::bead_points<3>(bead, k3, 0.8, model::Model::full, 0);
    test::close("open line: weights sum to its length", total(p), 15, 1e-12);
    double worst = 0;
    for (const auto &q : p)
      worst = std::max(worst, std::abs(q.normal.norm() - 1));
    test::close("unit normals", worst, 0, 1e-15);
    test::close("across the first segment", p.front().normal[0], 0, 0);
    test::close("across the second segment",
                std::abs(p.back().normal[0]),
                1,
                0);
    test::close("along runs from 0 to 1",
                p.front().along < 0.05 && p.back().along > 0.95,
                1,
                0);
    bead.closed = true;
    p           = beads::bead_points<3>(bead, k3, 0.8, model::Model::full, 0);
    test::close("closed: the perimeter",
                total(p),
                15 + std::hypot(10, 5),
                1e-12);
    bead.closed = false;
    bead.line   = {{-5, 3}, {5, 3}, {5, -2}};
    p = beads::bead_points<3>(bead, k3, 0.8, model::Model::quarter, 0);
    test::close("quarter: cut at x = 0 and y = 0", total(p), 5 + 3, 1e-12);
    bead.line = {{100, -1}, {100, 3}};
    p = beads::bead_points<3>(bead, k3, 0.78, model::Model::slice, 1.3671875);
    test::close("slice: its width", total(p), 1.3671875, 1e-12);
    bead.line = {{30, 0}};
    const model::Kinematics<2> axi(true), strip(false, 35);
    test::close(
      "axisymmetric: the ring",
      total(
        beads::bead_points<2>(bead, axi, 0.8, model::Model::axisymmetric, 0)),
      2 * M_PI * 30,
      1e-12);
    test::close(
      "plane strain: the width",
      total(
        beads::bead_points<2>(bead, strip, 0.8, model::Model::plane_strain, 0)),
      35,
      1e-12);
  }
} // namespace

int main()
{
  bead_model();
  lines();
  return test::result();
}
