// A plane-strain strip bent into the fully plastic range (rigid-perfectly
// plastic, the end x = L/2 turning about the mid-plane), its end state and
// release, and the measure of its springback: the fitted curvature change
// of the mid-plane (tests springback_bending and trimmed_release).
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/springback/release.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/state.h>

#include "state_problem.h"

#include <cmath>
#include <map>

namespace bent_strip
{
  using namespace dealii;
  using namespace formsolve;

  const double L = 24, W = 1, T = 1, dt = 0.5, omega = 0.1;
  const double sigma0 = 100, E = 2e5, nu = 0.3;

  /// The end x = L/2 turning about its mid-plane at omega.
  class Bent : public test::StateProblem<2>
  {
  public:
    Bent(state::State<2> &state, const solver::Assembler<2> &assembler)
        : StateProblem(state, assembler, dt, true)
    {
      prescribe_velocities(
        [&](const Point<2> &p, const unsigned int c, double &value) {
          const bool end   = std::abs(p[0] - L / 2) < 1e-9;
          const bool pivot = std::abs(p[1] - T / 2) < 1e-9;
          value            = c == 0 ? omega * (p[1] - T / 2) : 0;
          return end && (c == 0 || pivot);
        });
      solve_velocity(1e-11);
    }
  };

  /// Forming element, layers, refinements; the release's degree (0: the
  /// forming's), the bound on the curvature's relative error and on a
  /// cell's residual stress error (over s') along and across the strip.
  struct Variant
  {
    unsigned int degree, layers, refinements, release;
    double       bound, residual_bound = 1, across_bound = 1;
  };

  parameters::Run strip(const double r, const Variant &v)
  {
    parameters::Run prm =
      test::plane_strain_strip(L, W, T, {v.degree, v.layers, v.refinements});
    prm.material.strength_coefficient = sigma0;
    prm.material.hardening_exponent   = 0;
    prm.material.limiting_strain_rate = 1e-7;
    prm.material.young_modulus        = E;
    prm.material.poisson_ratio        = nu;
    prm.springback.enabled            = true;
    prm.springback.degree             = v.release;
    if (r != 1)
      {
        prm.material.anisotropy.criterion = parameters::YieldCriterion::hill48;
        prm.material.anisotropy.r_values  = {r};
      }
    return prm;
  }

  /// The displacement u_z and x of the owned mid-plane z DoFs.
  std::vector<std::pair<double, double>>
  mid_plane(const springback::Release<2> &release, const state::State<2> &s)
  {
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(*s.mapping,
                                         release.dof_handler(),
                                         points);
    const auto &fe    = release.dof_handler().get_fe();
    const auto  owned = release.dof_handler().locally_owned_dofs();
    std::vector<types::global_dof_index>      dofs(fe.n_dofs_per_cell());
    std::map<types::global_dof_index, double> x;
    for (const auto &cell : release.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && release.in_part(cell))
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 1 &&
                owned.is_element(dofs[i]) &&
                std::abs(points[dofs[i]][1] - T / 2) < 1e-9)
              x[dofs[i]] = points[dofs[i]][0];
        }
    std::vector<std::pair<double, double>> out;
    for (const auto &[i, xi] : x)
      out.emplace_back(xi, release.displacement()[i]);
    return out;
  }

  /// The curvature change: u_z = a + (kappa/2) x^2 fitted for x <= L/2 -
  /// 3 T (away from the end's Saint-Venant zone), all ranks.
  double curvature(const std::vector<std::pair<double, double>> &u,
                   const MPI_Comm                                comm,
                   const double                                  end = L / 2)
  {
    // Normal equations of [1, x^2/2].
    std::vector<double> m(5, 0.);
    for (const auto &[x, w] : u)
      if (x <= end - 3 * T)
        {
          const double q = 0.5 * x * x;
          m[0] += 1;
          m[1] += q;
          m[2] += q * q;
          m[3] += w;
          m[4] += q * w;
        }
    Utilities::MPI::sum(m, comm, m);
    return (m[0] * m[4] - m[1] * m[3]) / (m[0] * m[2] - m[1] * m[1]);
  }

  struct Bending
  {
    explicit Bending(const parameters::Run &p)
        : prm(p)
        , material(prm.material)
        , law(prm.material)
        , state(prm, MPI_COMM_WORLD)
        , assembler(material,
                    state.kinematics,
                    state.reference_mapping,
                    prm.mesh.degree)
        , update(material,
                 state.kinematics,
                 state.reference_mapping,
                 prm.mesh.degree)
    {
      state.create_mesh();
      problem = std::make_unique<Bent>(state, assembler);
      end_state();
    }
    /// The history of one step at the current velocity (strain, mean
    /// stress), the mesh left as it was.
    void end_state()
    {
      state.velocity_ghost = state.velocity;
      update.advance(state.dof_handler,
                     *state.mapping,
                     state.velocity_ghost,
                     dt,
                     state.history);
    }
    parameters::Run                   prm;
    const material::RigidViscoplastic material;
    const material::ReleaseLaw        law;
    state::State<2>                   state;
    const solver::Assembler<2>        assembler;
    const state::HistoryUpdate<2>     update;
    std::unique_ptr<Bent>             problem;

    /// The release of the end state, with the reactions of the prescribed
    /// end as the tools' forces.
    std::unique_ptr<springback::Release<2>> release() const
    {
      forces = problem->unconstrained_residual();
      return std::make_unique<springback::Release<2>>(state,
                                                      *state.mapping,
                                                      material,
                                                      law,
                                                      &forces);
    }
    mutable springback::VectorType forces;
  };

} // namespace bent_strip
