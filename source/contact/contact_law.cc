#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/contact/contact_law.h>

#include <cmath>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    NodalContactForce<dim> penalty_friction_force(const ContactPair<dim> &pair,
                                                  const double epsilon,
                                                  const double mu,
                                                  const double v0,
                                                  const double dt,
                                                  const bool   newton)
    {
      NodalContactForce<dim> out;
      out.normal_force = 0;
      if (!pair.active)
        return out;
      const Tensor<1, dim> &n = pair.normal;
      out.stiffness           = epsilon * dt * outer_product(n, n);
      out.normal_force        = epsilon * (pair.shift - pair.predicted_gap);
      out.force               = out.normal_force * n;
      if (mu == 0)
        return out;

      // Tangential slip velocity; n is fixed within a step (start geometry).
      const Tensor<1, dim> vt =
        pair.relative_velocity - (pair.relative_velocity * n) * n;
      const double s = vt.norm(), x = s / v0;
      // h(s) = (2/pi) atan(s/v0)/s and h'(s)/s, by series near s = 0.
      double h, dh_over_s;
      if (x < 1e-3)
        {
          h         = 2. / M_PI / v0 * (1. - x * x / 3.);
          dh_over_s = 2. / M_PI * (-2. / (3. * v0 * v0 * v0));
        }
      else
        {
          h         = 2. / M_PI * std::atan(x) / s;
          dh_over_s = 2. / M_PI *
                      (1. / (v0 * (1. + x * x)) / s - std::atan(x) / (s * s)) /
                      s;
        }
      Tensor<2, dim> Pt = unit_symmetric_tensor<dim>();
      Pt -= outer_product(n, n);
      out.force -= mu * out.normal_force * h * vt;
      out.stiffness += mu * out.normal_force * h * Pt;
      if (newton)
        {
          out.stiffness +=
            mu * out.normal_force * dh_over_s * outer_product(vt, vt);
          out.stiffness -= mu * h * epsilon * dt * outer_product(vt, n);
        }
      return out;
    }

    template NodalContactForce<2> penalty_friction_force(const ContactPair<2> &,
                                                         double,
                                                         double,
                                                         double,
                                                         double,
                                                         bool);
    template NodalContactForce<3> penalty_friction_force(const ContactPair<3> &,
                                                         double,
                                                         double,
                                                         double,
                                                         double,
                                                         bool);
  } // namespace contact
} // namespace formsolve
