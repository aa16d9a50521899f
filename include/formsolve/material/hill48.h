// Hill's 1948 quadratic anisotropy (../shared/method/anisotropy.md; doc/
// theory.md section 3a): the coefficients F, G, H, L, M, N normalised to
// G + H = 1 (sigma_bar is the rolling-direction uniaxial flow stress), from
// r-values, and the two metrics of the flow formulation in the orthotropy
// frame (1 = RD, 2 = TD, 3 = ND):
// - primal: sigma_bar^2 = sigma : P : sigma (Hill's criterion),
// - dual:   eps_bar_dot^2 = D : Q : D on the deviatoric rate, Q the
//   pseudo-inverse of P on deviators (it annihilates the identity), so that
//   sigma' = (sigma_bar/eps_bar_dot) Q : D does the plastic work
//   sigma' : D = sigma_bar eps_bar_dot.
// Both rotate with the material frame to the current one.
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <formsolve/material/mandel.h>
#include <formsolve/parameters/anisotropy.h>

#include <string>

namespace formsolve
{
  namespace material
  {
    using parameters::TransverseShear;

    struct Hill48
    {
      double F = 0.5, G = 0.5, H = 0.5, L = 1.5, M = 1.5, N = 1.5;

      /// von Mises: F = G = H = 1/2, L = M = N = 3/2.
      static Hill48 isotropic();
      /// Planar anisotropy from r0, r45, r90 (r-values at 0, 45, 90 degrees
      /// to RD): H = r0/(1+r0), G = 1/(1+r0), F = r0/(r90 (1+r0)),
      /// N = (r0+r90)(1+2 r45)/(2 r90 (1+r0)).
      static Hill48 from_r_values(const double          r0,
                                  const double          r45,
                                  const double          r90,
                                  const TransverseShear shear);
      /// Normal anisotropy: r0 = r45 = r90 = r.
      static Hill48 from_normal_r(const double r, const TransverseShear shear);
      /// From uniaxial flow stresses at 45 and 90 degrees and the balanced-
      /// biaxial one, over the RD flow stress: G + H = 1, F + H = 1/s90^2,
      /// F + G = 1/sb^2, F + G + 2N = 4/s45^2.
      static Hill48 from_yield_stresses(const double          s45,
                                        const double          s90,
                                        const double          sb,
                                        const TransverseShear shear);
      /// From the Material entries (von Mises if so chosen).
      static Hill48 from_parameters(const parameters::Anisotropy &a);

      /// FG + GH + HF.
      double determinant() const { return F * G + G * H + H * F; }

      /// P in the orthotropy frame: sigma_bar^2 = sigma : P : sigma.
      dealii::SymmetricTensor<4, 3> primal() const;
      /// Q in the orthotropy frame: eps_bar_dot^2 = D : Q : D.
      dealii::SymmetricTensor<4, 3> dual() const;

      /// S = (3/2 Q)^(1/2) on deviators, in Mandel's notation in the
      /// orthotropy frame: eps_bar_dot^2 = 2/3 |S D|^2, so that the von Mises
      /// law of the mapped rate S D gives Hill's (doc/theory.md, eq. 3b). The
      /// deviatoric projector for von Mises.
      Mandel6x6 root() const;

      /// "key = value" lines: F, G, H, L, M, N, and r and sigma/sigma_0 at
      /// 0, 45, 90 degrees (run summary; the screen shows the same).
      std::string summary() const;

      /// Mean r-value (r0 + 2 r45 + r90)/4.
      double mean_r() const;

      /// r-value of uniaxial tension at @p angle (radians) to RD: width over
      /// thickness strain rate.
      double r_value(const double angle) const;
      /// Uniaxial flow stress at @p angle to RD over that along RD.
      double stress_ratio(const double angle) const;
    };

  } // namespace material
} // namespace formsolve
