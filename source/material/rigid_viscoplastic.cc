#include <formsolve/material/rigid_viscoplastic.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    RigidViscoplastic::RigidViscoplastic(const parameters::Material &p)
        : law(p)
        , coefficients(Hill48::from_parameters(p.anisotropy))
        , yld(p.anisotropy.non_quadratic()
                ? std::optional<Yld2004>(Yld2004::from_parameters(p.anisotropy))
                : std::nullopt)
        , root(yld ? to_mandel(SymmetricTensor<4, 3>(identity_tensor<3>()))
                   : coefficients.root())
        , iso(p.anisotropy.criterion == parameters::YieldCriterion::von_mises)
        , rolling(p.anisotropy.rolling_direction * M_PI / 180)
        , cutoff(p.limiting_strain_rate)
        , smooth(p.rigid_zone == parameters::RigidZone::smooth)
        , bulk(p.volumetric_penalty * p.stress_scale() /
               p.reference_strain_rate)
    {}

    PointResponse RigidViscoplastic::evaluate(const SymmetricTensor<2, 3> &D,
                                              const double strain_old,
                                              const double dt,
                                              const bool   newton) const
    {
      const SymmetricTensor<2, 3> e = deviator(D);
      return yld ? respond_dual(e, strain_old, dt, newton, nullptr)
                 : respond(e,
                           std::sqrt(2. / 3. * (e * e)),
                           strain_old,
                           dt,
                           newton);
    }

    PointResponse RigidViscoplastic::evaluate(const SymmetricTensor<2, 3> &D,
                                              const double     strain_old,
                                              const double     dt,
                                              const bool       newton,
                                              const Mandel6x6 &map,
                                              const Mandel6x6 *start) const
    {
      // S annihilates the identity: no deviator needed (the rotation of a
      // non-quadratic law keeps the trace, its deviator is taken).
      const SymmetricTensor<2, 3> e =
        from_mandel(transpose_multiply(map, to_mandel(D)));
      PointResponse out =
        yld ? respond_dual(deviator(e), strain_old, dt, newton, start)
            : respond(e, std::sqrt(2. / 3. * (e * e)), strain_old, dt, newton);
      out.deviatoric_stress =
        from_mandel(multiply(map, to_mandel(out.deviatoric_stress)));
      return out;
    }

    Mandel6x6 RigidViscoplastic::hill_map(const Tensor<2, 3> &frame) const
    {
      return multiply(mandel_rotation(frame), root);
    }

    PointResponse
    RigidViscoplastic::respond_dual(const SymmetricTensor<2, 3> &e,
                                    const double                 strain_old,
                                    const double                 dt,
                                    const bool                   newton,
                                    const Mandel6x6             *start) const
    {
      // s from grad g(s) = e (eq. 3e), then the von Mises law of the
      // pseudo-rate lambda 3/2 s whose von Mises rate is sigma_bar(s): its
      // stress 2 mu (lambda 3/2 s) is lambda times the law's, its beta
      // lambda^2 times (both multiply e (x) e), and 2 mu P_dev becomes 2 mu
      // lambda 3/2 (grad^2 g)^+ (doc/theory.md, eq. 3f).
      // The earlier iterate's compliance C (metric = C up to a factor that
      // the solve's scaling of its start removes): its s_k = C e_k, and
      // s_k + C (e - e_k) = C e (doc/theory.md, section 3b).
      SymmetricTensor<2, 3> guess;
      if (start)
        guess = from_mandel(multiply(*start, to_mandel(e)));
      const DualPoint d = solve_dual(*yld, e, start ? &guess : nullptr);
      statistics.add(d.iterations);
      const double  vm     = std::sqrt(1.5 * (d.stress * d.stress));
      const double  lambda = vm > 0 ? d.rate / vm : 1;
      PointResponse out =
        respond(lambda * 1.5 * d.stress, d.rate, strain_old, dt, newton);
      out.viscosity /= lambda;
      out.deviatoric_stress /= lambda;
      out.beta /= lambda * lambda;
      out.beta_plastic /= lambda * lambda;
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int c = 0; c < 6; ++c)
          out.metric[r][c] = (lambda * 1.5) * d.compliance[r][c];
      out.local_iterations = d.iterations;
      return out;
    }

    PointResponse RigidViscoplastic::respond(const SymmetricTensor<2, 3> &e,
                                             const double                 rate,
                                             const double strain_old,
                                             const double dt,
                                             const bool   newton) const
    {
      PointResponse out;
      out.equivalent_strain_rate = rate;
      out.strain_rate_deviator   = e;
      out.dual_rate              = rate;

      if (smooth)
        {
          // s_bar = s r/rho, rho = sqrt(r^2 + r_c^2) (eq. 3a): s' = 2/3
          // (s/rho) D'. Linear viscous for r << r_c, plastic for r >> r_c,
          // smooth in between, so that Newton's tangent does not jump where
          // points cross r_c.
          const double rho      = std::sqrt(rate * rate + cutoff * cutoff);
          const double strain   = strain_old + dt * rate;
          const double s        = law.value(strain, rho);
          out.dual_rate         = rho;
          out.flow_stress       = s * rate / rho;
          out.viscosity         = s / (3. * rho);
          out.deviatoric_stress = 2. * out.viscosity * e;
          out.beta              = 0;
          if (newton && rate > 0)
            {
              // d(s/rho)/dr = ds/(rho) - s r/rho^3, ds the total derivative
              // of s along eps = eps_n + dt r and rho(r); dr/dD' = 2/3 D'/r.
              const double ds = dt * law.d_strain(strain, rho) +
                                law.d_rate(strain, rho) * rate / rho;
              out.beta_plastic = -(4. / 9.) * s / (rho * rho * rho);
              out.beta = out.beta_plastic + (4. / 9.) * ds / (rho * rate);
            }
          return out;
        }

      if (rate <= cutoff)
        {
          // Rigid zone: linear viscous with the viscosity frozen at the cutoff,
          // continuous with the plastic branch at rate == cutoff.
          const double s        = law.value(strain_old + dt * cutoff, cutoff);
          out.viscosity         = s / (3. * cutoff);
          out.flow_stress       = s * rate / cutoff;
          out.deviatoric_stress = 2. * out.viscosity * e;
          out.beta              = 0;
          return out;
        }

      const double strain = strain_old + dt * rate;
      const double s      = law.value(strain, rate);
      // ds/drate along the implicit path: hardening through eps = eps_n +
      // dt*rate.
      const double ds =
        dt * law.d_strain(strain, rate) + law.d_rate(strain, rate);

      out.flow_stress       = s;
      out.viscosity         = s / (3. * rate);
      out.deviatoric_stress = 2. * out.viscosity * e;
      out.beta =
        newton ? (4. / 9.) * (ds * rate - s) / (rate * rate * rate) : 0.;
      out.beta_plastic = newton ? -(4. / 9.) * s / (rate * rate * rate) : 0.;
      return out;
    }

    SymmetricTensor<4, 3>
    RigidViscoplastic::tangent(const PointResponse         &m,
                               const SymmetricTensor<2, 3> &w_rate) const
    {
      const SymmetricTensor<2, 3> &e = m.strain_rate_deviator;
      SymmetricTensor<4, 3>        C =
        2. * m.viscosity *
          (yld ? from_mandel(m.metric) : deviator_tensor<3>()) +
        (m.beta - m.beta_plastic) * outer_product(e, e);
      if (m.beta_plastic != 0)
        C += 0.5 * m.beta_plastic *
             (outer_product(e, w_rate) + outer_product(w_rate, e));
      return C;
    }

    Mandel6x6 RigidViscoplastic::tangent(const PointResponse         &m,
                                         const SymmetricTensor<2, 3> &w_rate,
                                         const Mandel6x6             &map) const
    {
      // The general form in Mandel's notation, then M C M^T.
      static const Mandel6x6 dev = to_mandel(deviator_tensor<3>());
      const Mandel6x6       &P   = yld ? m.metric : dev;
      const Mandel6          e   = to_mandel(m.strain_rate_deviator),
                    w            = to_mandel(w_rate);
      const double mu2 = 2. * m.viscosity, b = m.beta - m.beta_plastic,
                   bp = 0.5 * m.beta_plastic;
      Mandel6x6 C;
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int c = 0; c < 6; ++c)
          C[r][c] =
            mu2 * P[r][c] + b * e[r] * e[c] + bp * (e[r] * w[c] + w[r] * e[c]);
      return multiply_transpose(multiply(map, C), map);
    }

    std::string RigidViscoplastic::criterion_summary() const
    {
      return yld ? yld->summary() : coefficients.summary();
    }
  } // namespace material
} // namespace formsolve
