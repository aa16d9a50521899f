// A free block pulled along x in one Newton-solved step or several (full
// 3-D model, RD at an angle to x), shared by the tension tests of the
// anisotropic criteria and of the material cards: the ends move apart
// along x; v_y = v_z = 0 at the corner (-L/2, -W/2, 0) and v_z = 0 at
// (-L/2, W/2, 0) (no rigid motion); plane strain holds the sides.
#pragma once

#include <formsolve/forming/assembler.h>
#include <formsolve/material/damage.h>
#include <formsolve/material/hill_orientation.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>

#include "state_problem.h"

#include <cmath>

namespace test
{
  using namespace dealii;
  using namespace formsolve;

  const double L = 4, W = 2, T = 1, V = 0.04, dt = 0.5; // mm, mm/s, s

  class Tension : public test::StateProblem<>
  {
  public:
    Tension(state::State<3>            &state,
            const solver::Assembler<3> &assembler,
            const bool                  plane_strain)
        : StateProblem(state, assembler, dt, false)
    {
      // v_x = 0 at x = -L/2 and V at x = L/2; v_y = v_z = 0 at the corner
      // (-L/2, -W/2, 0) and v_z = 0 at (-L/2, W/2, 0) (no rigid motion);
      // plane strain: v_y = 0 on y = +-W/2.
      prescribe_velocities(
        [&](const Point<3> &p, const unsigned int c, double &value) {
          const bool left   = std::abs(p[0] + L / 2) < 1e-9,
                     right  = std::abs(p[0] - L / 2) < 1e-9,
                     side   = std::abs(std::abs(p[1]) - W / 2) < 1e-9,
                     bottom = std::abs(p[2]) < 1e-9;
          value             = c == 0 && right ? V : 0.;
          if (c == 0)
            return left || right;
          if (c == 1)
            return plane_strain ? side : left && bottom && p[1] < 0;
          return left && bottom && side;
        });
    }

    void solve_flow() { solve_velocity(1e-11); }

    /// The x force on the end x = L/2: the unconstrained residual there.
    double end_force() const
    {
      return x_force(
        [](const Point<3> &p) { return std::abs(p[0] - L / 2) < 1e-9; });
    }
  };

  struct Measured
  {
    double r_value, stress_over_flow_stress;
    double oyane_per_axial_strain; // I over the step's axial strain
  };

  /// The law, the state and the operators of one block run, its mesh made.
  struct BlockRun
  {
    explicit BlockRun(const parameters::Run &prm)
        : material(prm.material)
        , damage(prm.material, material.mean_r())
        , state(prm, MPI_COMM_WORLD)
        , assembler(material, state.kinematics, state.reference_mapping, 1)
        , update(material,
                 state.kinematics,
                 state.reference_mapping,
                 1,
                 &damage)
    {
      state.create_mesh();
    }

    const material::RigidViscoplastic material;
    const material::DamageCriteria    damage;
    state::State<3>                   state;
    const solver::Assembler<3>        assembler;
    const state::HistoryUpdate<3>     update;
  };

  /// One step of tension along x with RD at @p theta (degrees) to x.
  inline Measured
  pull(parameters::Run prm, const double theta, const bool plane)
  {
    prm.material.anisotropy.rolling_direction = -theta;
    BlockRun    run(prm);
    auto       &state    = run.state;
    const auto &material = run.material;
    const auto &update   = run.update;
    Tension     tension(state, run.assembler, plane);
    tension.solve_flow();
    const double force = tension.end_force();

    // Rate and flow stress at the first point of a cell of this rank; the
    // plastic rates without the penalty's small volume rate.
    const auto [D, flow] = test::first_point(state, material, dt);
    double rate[3];
    for (unsigned int d = 0; d < 3; ++d)
      rate[d] = deviator(D)[d][d];
    const double area = W * T; // the step is solved on the initial block
    state.advance(dt, update);
    const double oyane = Utilities::MPI::max(
      state.dof_handler.begin_active()->is_locally_owned()
        ? state.history.get_data(state.dof_handler.begin_active())[0]->oyane
        : 0.,
      state.comm);
    return {rate[1] / rate[2], force / area / flow, oyane / (dt * rate[0])};
  }

  /// The block's parameters around @p prm's material: L x W x T, 1 x 2 x 1
  /// cells, no die and no holder.
  inline parameters::Run block(parameters::Run prm)
  {
    prm.geometry.model             = model::Model::full;
    prm.geometry.blank_shape       = parameters::BlankShape::rectangle;
    prm.geometry.blank_length      = L;
    prm.geometry.blank_width       = W;
    prm.geometry.thickness         = T;
    prm.mesh                       = {1, 2, 1};
    prm.tools.die.enabled          = false;
    prm.tools.blank_holder.enabled = false;
    return prm;
  }
} // namespace test
