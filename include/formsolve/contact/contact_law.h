// Nodal contact force: normal penalty and regularised Coulomb friction.
#pragma once

#include <formsolve/contact/contact_set.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    struct NodalContactForce
    {
      Tensor<1, dim> force;        // force of the tool on the sheet node (N)
      Tensor<2, dim> stiffness;    // -d(force)/d(node velocity) (N s/mm)
      double         normal_force; // >= 0 (N)
    };

    /// f = eps <s - g_pred> n (s: augmented Lagrangian shift, else 0) - mu f_n
    /// (2/pi) atan(|v_t|/v0) v_t/|v_t| (doc/theory.md, eq. 6). @p newton false
    /// gives the secant friction term.
    template <int dim>
    NodalContactForce<dim> penalty_friction_force(const ContactPair<dim> &pair,
                                                  const double epsilon,
                                                  const double friction,
                                                  const double v0,
                                                  const double dt,
                                                  const bool   newton);
  } // namespace contact
} // namespace formsolve
