// The orthotropy frame follows the material (doc/theory.md, section 3a):
// - the polar rotation of F = R U equals R for known R and U (stretch,
//   shear), and the frame of a deformed point is R times the initial one;
// - a Hill48 sheet turned rigidly by 90 degrees about TD (ND horizontal, as
//   in a cup wall) with the strain rate turned alike gives the turned stress
//   (every component, hence every invariant) to 1e-10 relative; the same
//   with the frame held fixed in space (what this test guards against)
//   changes the invariants by far more than 1 %.
// Quarter-free block (full 3-D model), 1 and 2 ranks.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/material/hill_orientation.h>
#include <formsolve/state/state.h>

#include "check.h"

#include <cmath>

using namespace dealii;
using namespace formsolve;

namespace
{
  Tensor<2, 3> rotation_about_y(const double angle)
  {
    Tensor<2, 3> R;
    R[0][0] = R[2][2] = std::cos(angle);
    R[0][2]           = std::sin(angle);
    R[2][0]           = -std::sin(angle);
    R[1][1]           = 1;
    return R;
  }

  /// x -> (M - I) x as a displacement.
  class Linear : public Function<3>
  {
  public:
    explicit Linear(const Tensor<2, 3> &A)
        : Function<3>(3)
        , A(A)
    {}
    double value(const Point<3> &x, const unsigned int c) const override
    {
      return (A * x)[c];
    }

  private:
    Tensor<2, 3> A;
  };

  /// The stresses at every point of this rank's cells for the velocity
  /// gradient @p L (constant), frames from the state's mapping, or the
  /// initial frame with @p fixed; the points' frames into @p frames.
  std::vector<SymmetricTensor<2, 3>>
  stresses(const state::State<3>             &state,
           const material::RigidViscoplastic &material,
           const Tensor<2, 3>                &L,
           const bool                         fixed,
           std::vector<Tensor<2, 3>>         &frames)
  {
    const QGauss<3>                    rule(2);
    model::CellKinematics<3>           k(state.kinematics,
                               *state.mapping,
                               state.fe,
                               rule,
                               update_jacobians,
                               &state.reference_mapping);
    material::HillOrientation<3>       o(material);
    const model::MaterialFrame<3>      frame(material.rolling_direction());
    const SymmetricTensor<2, 3>        D = symmetrize(L);
    std::vector<SymmetricTensor<2, 3>> out;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          k.reinit(cell);
          o.reinit(k);
          for (unsigned int q = 0; q < k.n_points(); ++q)
            frames.push_back(o.frame(q));
          for (unsigned int q = 0; q < k.n_points(); ++q)
            out.push_back(material
                            .evaluate(D,
                                      0.1,
                                      0.1,
                                      false,
                                      fixed ? material.hill_map(frame.initial())
                                            : *o.map(q))
                            .deviatoric_stress);
        }
    return out;
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // Polar decomposition of known factors.
  {
    Tensor<2, 3> U;
    U[0][0] = 1.3, U[1][1] = 0.8, U[2][2] = 1.1, U[0][1] = U[1][0] = 0.2;
    U[1][2] = U[2][1] = -0.1;
    Tensor<2, 3> R    = rotation_about_y(0.7);
    R = R * transpose(rotation_about_y(0.3)) * R; // any rotation
    test::close("polar rotation of R U",
                (model::polar_rotation<3>(R * U) - R).norm(),
                0,
                1e-12);
    Tensor<2, 2> U2, R2;
    U2[0][0] = 1.5, U2[1][1] = 0.6, U2[0][1] = U2[1][0] = 0.3;
    R2[0][0] = R2[1][1] = std::cos(1.2);
    R2[0][1]            = -std::sin(1.2);
    R2[1][0]            = std::sin(1.2);
    test::close("polar rotation of R U (2-D)",
                (model::polar_rotation<2>(R2 * U2) - R2).norm(),
                0,
                1e-12);
  }

  parameters::Run prm;
  prm.geometry.model        = model::Model::full;
  prm.geometry.blank_shape  = parameters::BlankShape::rectangle;
  prm.geometry.blank_length = 4;
  prm.geometry.blank_width  = 2;
  prm.geometry.thickness    = 1;
  prm.mesh                  = {2, 2, 1};
  auto &a                   = prm.material.anisotropy;
  a.criterion               = parameters::YieldCriterion::hill48;
  a.r_values                = {2.1, 1.6, 2.7};
  a.rolling_direction       = 30;
  const material::RigidViscoplastic material(prm.material);
  state::State<3>                   state(prm, MPI_COMM_WORLD);
  state.create_mesh();

  Tensor<2, 3> L0; // stretch, shear and spin
  L0[0][0] = 1, L0[1][1] = -0.3, L0[2][2] = -0.7, L0[0][1] = 0.4;
  L0[1][2] = 0.2, L0[2][0] = -0.1;
  std::vector<Tensor<2, 3>> unused, frames;
  const auto before = stresses(state, material, L0, false, unused);

  const Tensor<2, 3> R = rotation_about_y(M_PI / 2);
  VectorTools::interpolate(state.reference_mapping,
                           state.dof_handler,
                           Linear(R - unit_symmetric_tensor<3>()),
                           state.displacement);
  state.update_mapping();
  const Tensor<2, 3> L     = R * L0 * transpose(R);
  const auto         after = stresses(state, material, L, false, frames);
  const auto         fixed = stresses(state, material, L, true, unused);

  // The frame at a point: R times the initial one.
  {
    double worst = 0;
    for (const auto &f : frames)
      worst =
        std::max(worst,
                 (f - R * model::MaterialFrame<3>(M_PI / 6).initial()).norm());
    test::close("frame = R times the initial frame",
                Utilities::MPI::max(worst, MPI_COMM_WORLD),
                0,
                1e-12);
  }

  double turned = 0, invariant_fixed = 0;
  for (unsigned int i = 0; i < before.size(); ++i)
    {
      const SymmetricTensor<2, 3> expected =
        symmetrize(R * Tensor<2, 3>(before[i]) * transpose(R));
      turned =
        std::max(turned, (after[i] - expected).norm() / before[i].norm());
      invariant_fixed =
        std::max(invariant_fixed,
                 std::abs(fixed[i].norm() / before[i].norm() - 1) +
                   std::abs(determinant(fixed[i]) / determinant(before[i]) -
                            1));
    }
  test::close("turned sheet: stress = R stress R^T (relative)",
              Utilities::MPI::max(turned, MPI_COMM_WORLD),
              0,
              1e-10);
  const double f = Utilities::MPI::max(invariant_fixed, MPI_COMM_WORLD);
  std::cout << "a frame fixed in space changes the invariants by " << f << "\n";
  test::close("a fixed frame is detected", f > 0.01, 1, 0);
  return test::result();
}
