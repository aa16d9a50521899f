// The nodal contact law: the penalty force equals eps * penetration, friction
// opposes slip with mu * normal force, and the consistent stiffness equals the
// finite-difference derivative of the force.
#include <formsolve/contact/contact_law.h>

#include "check.h"

using namespace dealii;
using namespace formsolve::contact;

int main()
{
  const double eps = 2e4, mu = 0.1, v0 = 1e-2, dt = 0.25, gap = 1e-3;
  Tensor<1, 3> n;
  n[0] = 0.6, n[2] = 0.8;
  auto pair_at = [&](const Tensor<1, 3> &w) {
    ContactPair<3> p;
    p.node = 0, p.tool = 0, p.gap = gap, p.normal = n, p.relative_velocity = w;
    p.predicted_gap = gap + (n * w) * dt;
    p.area = 1, p.active = p.predicted_gap < 0;
    return p;
  };
  Tensor<1, 3> w;
  w[0] = -0.3, w[1] = 0.7, w[2] = -0.2; // slipping and closing
  const auto   f   = penalty_friction_force(pair_at(w), eps, mu, v0, dt, true);
  const double pen = -(gap + (n * w) * dt);
  test::close("normal force = eps * penetration",
              f.normal_force,
              eps * pen,
              1e-9);
  test::close("normal component of the force", f.force * n, eps * pen, 1e-9);
  const Tensor<1, 3> wt = w - (w * n) * n;
  const Tensor<1, 3> ft = f.force - (f.force * n) * n;
  test::close("friction magnitude = mu f_n (2/pi) atan(|vt|/v0)",
              ft.norm(),
              mu * eps * pen * 2 / M_PI * std::atan(wt.norm() / v0),
              1e-9);
  test::close("friction opposes slip (cosine)",
              ft * wt / (ft.norm() * wt.norm()),
              -1,
              1e-12);

  // Stiffness against central differences, for slipping and near-sticking.
  for (const double scale : {1., 1e-3})
    {
      Tensor<1, 3> ws = w;
      ws[1] *= scale;
      const auto fs =
        penalty_friction_force(pair_at(ws), eps, mu, v0, dt, true);
      double       worst = 0, ref = 0;
      const double h = 1e-7;
      for (unsigned int j = 0; j < 3; ++j)
        {
          Tensor<1, 3> wp = ws, wm = ws;
          wp[j] += h, wm[j] -= h;
          const auto fp =
            penalty_friction_force(pair_at(wp), eps, mu, v0, dt, true);
          const auto fm =
            penalty_friction_force(pair_at(wm), eps, mu, v0, dt, true);
          for (unsigned int i = 0; i < 3; ++i)
            {
              const double fd = -(fp.force[i] - fm.force[i]) / (2 * h);
              worst = std::max(worst, std::abs(fd - fs.stiffness[i][j]));
              ref   = std::max(ref, std::abs(fs.stiffness[i][j]));
            }
        }
      test::close("stiffness vs finite differences (slip scale " +
                    std::to_string(scale) + ")",
                  worst / ref,
                  0,
                  1e-5);
    }

  // Separated: no force.
  Tensor<1, 3> away = n;
  const auto f0 = penalty_friction_force(pair_at(away), eps, mu, v0, dt, true);
  test::close("no force when the predicted gap is open", f0.force.norm(), 0, 0);
  return test::result();
}
