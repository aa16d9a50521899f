// Plane-strain pure bending of a rigid-perfectly-plastic strip (length L
// along x, width b along y, thickness t along z): the ends x = -+L/2 turn
// about the mid-plane, v_x = -+omega (z - t/2); v_y = 0 everywhere (plane
// strain); v_z = 0 at the ends' mid-plane removes the rigid z motion. The
// exact flow is uniform along x: rate of curvature 2 omega/L, sigma_z = 0.
// One Newton solve on a formsolve State (the library's mesh, assembler and
// history).
#pragma once

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/parameters/parameters.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/mumps_solver.h>
#include <formsolve/solver/newton_solver.h>
#include <formsolve/state/state.h>

#include "check.h"
#include "toy_problem.h"

namespace test
{
  using namespace dealii;
  using namespace formsolve;

  struct StripSize
  {
    double L = 4, b = 1, t = 1, omega = 0.1;
  };

  inline parameters::Run bending_run(const StripSize            &s,
                                     const parameters::Mesh     &mesh,
                                     const parameters::Material &material)
  {
    parameters::Run prm;
    prm.geometry.model        = model::Model::full;
    prm.geometry.blank_shape  = parameters::BlankShape::rectangle;
    prm.geometry.blank_length = s.L;
    prm.geometry.blank_width  = s.b;
    prm.geometry.thickness    = s.t;
    prm.mesh                  = mesh;
    prm.material              = material;
    return prm;
  }

  class BendingStrip : public ToyProblem
  {
  public:
    BendingStrip(const StripSize            &size,
                 const parameters::Mesh     &mesh,
                 const parameters::Material &material_prm,
                 const double                dt)
        : size(size)
        , dt(dt)
        , prm(bending_run(size, mesh, material_prm))
        , material(prm.material)
        , state(prm, MPI_COMM_WORLD)
        , assembler(material,
                    state.kinematics,
                    state.reference_mapping,
                    mesh.degree)
        , linear(parameters::LinearSolver(), true)
    {
      state.create_mesh();
      make_constraints(bc, true);
      make_constraints(homogeneous, false);
      DynamicSparsityPattern dsp(state.relevant);
      DoFTools::make_sparsity_pattern(state.dof_handler,
                                      dsp,
                                      homogeneous,
                                      false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 state.owned,
                                                 MPI_COMM_WORLD,
                                                 state.relevant);
      matrix.reinit(state.owned, state.owned, dsp, MPI_COMM_WORLD);
      residual.reinit(state.owned, MPI_COMM_WORLD);
      ghost.reinit(state.owned, state.relevant, MPI_COMM_WORLD);
    }

    /// Newton from the end rotation alone; the solution stays in ghost().
    void solve_flow()
    {
      VectorType v(state.owned, MPI_COMM_WORLD);
      bc.distribute(v);
      parameters::NonlinearSolver p;
      p.residual_tolerance    = 1e-9;
      p.correction_tolerance  = 1e-9;
      p.max_line_search_steps = 8;
      const auto report =
        solve_from(solver::NewtonSolver(p,
                                        ConditionalOStream(std::cout, false)),
                   v);
      close("Newton converged", report.converged, 1, 0);
      ghost = v;
    }

    double assemble(const VectorType &v, const bool newton) override
    {
      ghost = v;
      scale = assembler.assemble_body(state.dof_handler,
                                      state.reference_mapping,
                                      homogeneous,
                                      ghost,
                                      state.history,
                                      dt,
                                      newton,
                                      &matrix,
                                      residual);
      return residual.l2_norm();
    }
    double force_scale() const override { return scale; }
    double directional_derivative(const VectorType &w) const override
    {
      return residual * w;
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      VectorType rhs(residual);
      rhs *= -1.;
      const auto its = linear.solve(matrix, dv, rhs);
      homogeneous.distribute(dv);
      return its;
    }

    const StripSize                   size;
    const double                      dt;
    const parameters::Run             prm;
    const material::RigidViscoplastic material;
    state::State<3>                   state;
    const solver::Assembler<3>        assembler;
    VectorType                        ghost; // the velocity (mm/s)

  private:
    void make_constraints(AffineConstraints<double> &c, const bool values)
    {
      const auto                                 &dh = state.dof_handler;
      std::map<types::global_dof_index, Point<3>> points;
      DoFTools::map_dofs_to_support_points(state.reference_mapping, dh, points);
      c.clear();
      c.reinit(state.relevant);
      std::vector<types::global_dof_index> dofs(state.fe.n_dofs_per_cell());
      for (const auto &cell : dh.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const unsigned int comp =
                  state.fe.system_to_component_index(i).first;
                const Point<3> &x = points[dofs[i]];
                const bool end = std::abs(std::abs(x[0]) - size.L / 2) < 1e-9;
                const bool mid = std::abs(x[2] - size.t / 2) < 1e-9;
                double     value;
                if (comp == 1)
                  value = 0;
                else if (comp == 0 && end)
                  value =
                    (x[0] > 0 ? 1 : -1) * size.omega * (x[2] - size.t / 2);
                else if (comp == 2 && end && mid)
                  value = 0;
                else
                  continue;
                if (!c.is_constrained(dofs[i]))
                  {
                    c.add_line(dofs[i]);
                    c.set_inhomogeneity(dofs[i], values ? value : 0.);
                  }
              }
          }
      c.close();
    }

    AffineConstraints<double> bc, homogeneous;
    solver::MatrixType        matrix;
    VectorType                residual;
    solver::MumpsSolver       linear;
    double                    scale = 0;
  };
} // namespace test
