// Homogeneous uniaxial tension of a block (quarter model, ends pulled apart
// by prescribed velocities, lateral faces free): at every quadrature point
// Oyane's integral equals (1/b)(1/3 + a) eps_bar, since sigma_m / sigma_bar
// = 1/3 in uniaxial tension, and the Cockcroft-Latham integral equals
// sum_k sigma_bar(eps_k) d eps_k (sigma_1 = sigma_bar), both to 1e-6
// relative, after several steps with the geometry updated.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/linear/mumps_solver.h>
#include <formsolve/newton/newton_solver.h>
#include <formsolve/state/state.h>

#include "block_tension.h"
#include "check.h"
#include "state_problem.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double h = 2, V = 0.2, dt = 0.25; // height (mm), end speed (mm/s)

  class Tension : public test::StateProblem<>
  {
  public:
    Tension(state::State<3>               &state,
            const solver::Assembler<3>    &assembler,
            const state::HistoryUpdate<3> &update)
        : StateProblem(state, assembler, dt, false)
        , update(update)
    {
      // The state's constraints (symmetry planes x = 0, y = 0) plus v_z = 0
      // at z = 0 and v_z = V at z = h.
      for (auto *c : {&bc, &homogeneous})
        {
          c->clear();
          c->reinit(state.relevant);
          c->merge(state.constraints);
        }
      std::map<types::global_dof_index, Point<3>> points;
      DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                           state.dof_handler,
                                           points);
      std::vector<types::global_dof_index> dofs(state.fe.n_dofs_per_cell());
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const double z = points[dofs[i]][2];
                if (state.fe.system_to_component_index(i).first != 2 ||
                    (z > 1e-9 && z < h - 1e-9) || bc.is_constrained(dofs[i]))
                  continue;
                for (auto *c : {&bc, &homogeneous})
                  {
                    c->add_line(dofs[i]);
                    c->set_inhomogeneity(dofs[i], c == &bc && z > 1 ? V : 0.);
                  }
              }
          }
      bc.close();
      homogeneous.close();
      setup_system();
    }

    void step()
    {
      solve_velocity(1e-11);
      state.advance(dt, update);
    }

  private:
    const state::HistoryUpdate<3> &update;
  };
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  parameters::Run                  prm;
  prm.geometry.model                = model::Model::quarter;
  prm.geometry.blank_shape          = parameters::BlankShape::rectangle;
  prm.geometry.blank_length         = 2;
  prm.geometry.blank_width          = 2;
  prm.geometry.thickness            = h;
  prm.mesh                          = {1, 2, 1};
  prm.material.strength_coefficient = 500;
  prm.material.hardening_exponent   = 0.2;
  prm.material.oyane_a              = 0.1;
  prm.material.oyane_b              = 0.3;
  prm.material.cockcroft_latham     = 300;
  prm.tools.die.enabled             = false;
  prm.tools.blank_holder.enabled    = false;

  test::BlockRun run(prm);
  auto          &state  = run.state;
  const auto    &damage = run.damage;
  Tension        tension(state, run.assembler, run.update);

  // The expected Cockcroft-Latham integral along the discrete strain path:
  // sigma_bar at the end-of-step strain times the step's strain increment.
  double eps = 0, W = 0;
  for (unsigned int k = 0; k < 6; ++k)
    {
      tension.step();
      const auto h0 = state.history.get_data(state.dof_handler.begin_active());
      const double d_eps = h0[0]->strain - eps;
      eps                = h0[0]->strain;
      W += 500 * std::pow(0.002 + eps, 0.2) * d_eps;
    }
  double worst_oyane = 0, worst_cl = 0, worst_uniform = 0;
  for (const auto &cell : state.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &p : state.history.get_data(cell))
        {
          const double oyane = (1. / 0.3) * (1. / 3. + 0.1) * p->strain;
          worst_oyane = std::max(worst_oyane, std::abs(p->oyane / oyane - 1));
          worst_cl =
            std::max(worst_cl,
                     std::abs(damage.cockcroft_latham(p->cockcroft_latham) /
                                (W / 300) -
                              1));
          worst_uniform =
            std::max(worst_uniform, std::abs(p->strain / eps - 1));
        }
  std::cout << "equivalent strain after 6 steps: " << eps << "\n";
  test::close("homogeneous strain (relative spread)", worst_uniform, 0, 1e-9);
  test::close("Oyane I / ((1/b)(1/3 + a) eps_bar) - 1", worst_oyane, 0, 1e-6);
  test::close("Cockcroft-Latham C / (int sigma_bar d eps / C_crit) - 1",
              worst_cl,
              0,
              1e-6);
  return test::result();
}
