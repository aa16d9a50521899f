// Plane-strain pure bending of a rigid-perfectly-plastic strip
// (bending_strip.h): the limit moment from the computed dissipation,
// M = P / (2 omega), against the closed form (2/sqrt 3) sigma0 b t^2 / 4.
// Locking elements overshoot it.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <formsolve/model/cell_kinematics.h>

#include "bending_strip.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double sigma0 = 100, dt = 1e-3;

  parameters::Material perfectly_plastic()
  {
    parameters::Material m; // perfectly plastic, sigma_0
    m.strength_coefficient = sigma0;
    m.hardening_exponent   = 0;
    m.limiting_strain_rate = 1e-7;
    return m;
  }

  /// Plastic power int sigma' : D dV plus the volumetric term (W = N mm/s).
  double internal_power(const test::BendingStrip &strip)
  {
    const auto              &s      = strip.state;
    const unsigned int       degree = s.fe.degree;
    const QGauss<3>          full(degree + 1), reduced(degree);
    model::CellKinematics<3> kf(s.kinematics, s.reference_mapping, s.fe, full);
    model::CellKinematics<3> kr(s.kinematics,
                                s.reference_mapping,
                                s.fe,
                                reduced);
    std::vector<SymmetricTensor<2, 3>> D, Dr;
    double                             power = 0;
    for (const auto &cell : s.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          kf.reinit(cell);
          kr.reinit(cell);
          kf.rates(strip.state.velocity_ghost, D);
          kr.rates(strip.state.velocity_ghost, Dr);
          const auto h = s.history.get_data(cell);
          for (unsigned int q = 0; q < kf.n_points(); ++q)
            power += strip.material.evaluate(D[q], h[q]->strain, dt, false)
                       .deviatoric_stress *
                     D[q] * kf.dV(q);
          for (unsigned int q = 0; q < kr.n_points(); ++q)
            power += strip.material.bulk_viscosity() * trace(Dr[q]) *
                     trace(Dr[q]) * kr.dV(q);
        }
    return Utilities::MPI::sum(power, MPI_COMM_WORLD);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const test::StripSize            s;
  const double exact = 2. / std::sqrt(3.) * sigma0 * s.b * s.t * s.t / 4.;
  std::cout << "closed-form limit moment: " << exact << " N mm\n";
  for (const auto &[degree, layers] : {std::pair{2u, 2u}, std::pair{1u, 4u}})
    {
      const test::StripSize size;
      test::BendingStrip    strip(size,
                               {degree, layers, 2},
                               perfectly_plastic(),
                               dt);
      strip.solve_flow();
      const double M = internal_power(strip) / (2 * size.omega);
      std::cout << "Q" << degree << ", " << layers << " layers: M = " << M
                << " N mm, relative error " << (M - exact) / exact << "\n";
      test::close("Q" + std::to_string(degree) + " " + std::to_string(layers) +
                    " layers: M / M_exact",
                  M / exact,
                  1.,
                  0.03);
    }
  return test::result();
}
