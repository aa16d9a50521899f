#include <formsolve/material/rigid_viscoplastic.h>

#include <cmath>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    RigidViscoplastic::RigidViscoplastic(const parameters::Material &p)
        : law(p)
        , cutoff(p.limiting_strain_rate)
        , bulk(p.volumetric_penalty * p.strength_coefficient /
               p.reference_strain_rate)
    {}

    PointResponse RigidViscoplastic::evaluate(const SymmetricTensor<2, 3> &D,
                                              const double strain_old,
                                              const double dt,
                                              const bool   newton) const
    {
      PointResponse               out;
      const SymmetricTensor<2, 3> e    = deviator(D);
      const double                rate = std::sqrt(2. / 3. * (e * e));
      out.equivalent_strain_rate       = rate;
      out.strain_rate_deviator         = e;

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
  } // namespace material
} // namespace formsolve
