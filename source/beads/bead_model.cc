#include <formsolve/beads/bead_model.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace beads
  {
    double wrap_angle(const BeadGeometry &g, const double p, const double t)
    {
      // Mid-surface radii over shoulder and bead; their centres lie a =
      // rho_s + rho_b apart across the groove and b = rho_s + rho_b - p
      // apart along z. The sheet runs on the circles' inner common
      // tangent, at angle asin((rho_s + rho_b) / |(a, b)|) - atan(b / a)
      // to the flange.
      const double rs = g.shoulder_radius + t / 2, rb = g.bead_radius + t / 2;
      const double a = rs + rb, b = std::max(rs + rb - std::max(p, 0.), 0.);
      const double d = std::hypot(a, b);
      return std::max(std::asin(std::min((rs + rb) / d, 1.)) - std::atan2(b, a),
                      0.);
    }

    BeadForces bead_forces(const BeadGeometry &g,
                           const double        p,
                           const double        t,
                           const double        sigma_ps)
    {
      BeadForces out;
      out.wrap_angle = wrap_angle(g, p, t);
      if (out.wrap_angle <= 0)
        return out;
      const double theta = out.wrap_angle, mu = g.friction;
      // Fully plastic moment per unit length M_p = sigma_ps t^2 / 4; a bend
      // to mid-surface radius rho or its unbend each do M_p / rho of work
      // per unit area drawn through.
      const double mp = sigma_ps * t * t / 4;
      const double ds = mp / (g.shoulder_radius + t / 2),
                   db = mp / (g.bead_radius + t / 2);
      // Shoulder 1 (arc theta), bead (2 theta), shoulder 2 (theta); the
      // tension entering the bead is 0 (what the flange adds ahead of it is
      // the simulation's own).
      const double t1    = ds * std::exp(mu * theta) + ds;
      const double t2_in = t1 + db, t2 = t2_in * std::exp(2 * mu * theta) + db;
      const double t3 = (t2 + ds) * std::exp(mu * theta) + ds;
      out.restraining = t3;
      // The bead holds the sheet deflected by theta on both sides: the
      // tension there, times sin(theta), pushes the bead out of its groove.
      out.opening = (t2_in + (t2 - db)) * std::sin(theta);
      return out;
    }

    double passage_strain(const BeadGeometry &g, const double t)
    {
      // Surface strain of a bend to mid-surface radius rho: t / (2 rho);
      // its mean over the thickness half that; equivalent in plane strain
      // 2 / sqrt(3) of it. Four shoulder and two bead bends.
      const double rs = g.shoulder_radius + t / 2, rb = g.bead_radius + t / 2;
      return 2. / std::sqrt(3.) * t / 4 * (4 / rs + 2 / rb);
    }
  } // namespace beads
} // namespace formsolve
