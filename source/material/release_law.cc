#include <deal.II/base/exceptions.h>
#include <deal.II/physics/transformations.h>

#include <formsolve/material/release_law.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    ReleaseLaw::ReleaseLaw(const parameters::Material &p)
        : law(p)
        , rate0(p.reference_strain_rate)
        , isotropic(p.anisotropy.criterion ==
                    parameters::YieldCriterion::von_mises)
        , hill_primal(Hill48::from_parameters(p.anisotropy).primal())
        , E(p.young_modulus)
        , G(E / (2 * (1 + p.poisson_ratio)))
        , K(E / (3 * (1 - 2 * p.poisson_ratio)))
    {
      AssertThrow(std::isfinite(E) && E > 0,
                  ExcMessage("Material/Young's modulus must be given for "
                             "springback"));
      C = 2 * G * deviator_tensor<3>() +
          K * outer_product(unit_symmetric_tensor<3>(),
                            unit_symmetric_tensor<3>());
    }

    SymmetricTensor<4, 3> ReleaseLaw::metric(const Tensor<2, 3> &frame) const
    {
      if (isotropic)
        return 1.5 * deviator_tensor<3>();
      return Physics::Transformations::basis_transformation(hill_primal, frame);
    }

    double ReleaseLaw::equivalent(const SymmetricTensor<2, 3> &s,
                                  const SymmetricTensor<4, 3> &P)
    {
      return std::sqrt(std::max(0., s * (P * s)));
    }

    double ReleaseLaw::yield_stress(const double eq_strain) const
    {
      return law.value(eq_strain, rate0);
    }

    double ReleaseLaw::return_parameter(const SymmetricTensor<2, 3> &trial,
                                        const double                 eq_strain,
                                        const SymmetricTensor<4, 3> &P) const
    {
      // F(gamma) = sigma_bar(gamma) - h(eps + gamma sigma_bar(gamma)):
      // positive at 0, decreasing; Newton kept inside a bracket.
      const SymmetricTensor<4, 3> I  = identity_tensor<3>();
      double                      lo = 0, hi = -1, gamma = 0;
      for (unsigned int it = 0; it < 100; ++it)
        {
          const SymmetricTensor<4, 3> A   = invert(I + 2 * G * gamma * P);
          const SymmetricTensor<2, 3> s   = A * trial;
          const double                sb  = equivalent(s, P);
          const double                eps = eq_strain + gamma * sb;
          const double h = yield_stress(eps), dh = law.d_strain(eps, rate0);
          const double F = sb - h;
          if (std::abs(F) <= 1e-13 * h)
            return gamma;
          (F > 0 ? lo : hi)                = gamma;
          const SymmetricTensor<2, 3> n    = (P * s) / sb;
          const double                dsb  = -2 * G * (n * (A * (P * s)));
          const double                dF   = dsb * (1 - dh * gamma) - dh * sb;
          double                      next = dF < 0 ? gamma - F / dF : -1;
          if (hi < 0 && !(next > lo))
            next = lo > 0 ? 2 * lo : 1 / (2 * G);
          else if (hi >= 0 && !(next > lo && next < hi))
            next = 0.5 * (lo + hi);
          gamma = next;
        }
      std::ostringstream m;
      m << "springback: the return to the yield surface did not converge "
           "(equivalent plastic strain "
        << eq_strain << ", trial equivalent stress " << equivalent(trial, P)
        << " MPa)";
      AssertThrow(false, ExcMessage(m.str()));
      return gamma;
    }

    ReleaseLaw::Response
    ReleaseLaw::respond(const SymmetricTensor<2, 3> &end_stress,
                        const SymmetricTensor<2, 3> &strain,
                        const double                 eq_strain,
                        const SymmetricTensor<4, 3> &P) const
    {
      Response                    r;
      const SymmetricTensor<2, 3> trial = end_stress + C * strain;
      const double                sy    = yield_stress(eq_strain);
      r.trial_ratio                     = equivalent(trial, P) / sy;
      if (r.trial_ratio <= 1 + 1e-10)
        {
          r.stress  = trial;
          r.tangent = C;
          return r;
        }
      // The return (doc/theory.md, eq. 12b) and its consistent tangent
      // C_alg = A C - (1 - h' gamma) (2G)^2 sigma_bar (A n)(x)(A n) / den.
      const double                gamma = return_parameter(trial, eq_strain, P);
      const SymmetricTensor<4, 3> A =
        invert(SymmetricTensor<4, 3>(identity_tensor<3>()) + 2 * G * gamma * P);
      r.stress                       = A * trial;
      const double                sb = equivalent(r.stress, P);
      const SymmetricTensor<2, 3> n  = (P * r.stress) / sb;
      const SymmetricTensor<2, 3> An = A * n;
      r.plastic_strain               = gamma * sb;
      const double dh  = law.d_strain(eq_strain + r.plastic_strain, rate0);
      const double a   = 1 - dh * gamma;
      const double den = dh * sb + a * 2 * G * sb * (n * An);
      r.tangent = A * C - (a * 4 * G * G * sb / den) * outer_product(An, An);
      r.yielded = true;
      return r;
    }
  } // namespace material
} // namespace formsolve
