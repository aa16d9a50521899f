// Plane-strain pure bending of a rigid-perfectly-plastic strip (length L
// along x, width b along y, thickness t along z): the ends x = -+L/2 turn
// about the mid-plane, v_x = -+omega (z - t/2); v_y = 0 everywhere (plane
// strain); v_z = 0 at the ends' mid-plane removes the rigid z motion. The
// exact flow is uniform along x: rate of curvature 2 omega/L, sigma_z = 0.
// One Newton solve on a formsolve State (the library's mesh, assembler and
// history; state_problem.h).
#pragma once

#include "state_problem.h"

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

  class BendingStrip : public StateProblem<>
  {
  public:
    BendingStrip(const StripSize            &size,
                 const parameters::Mesh     &mesh,
                 const parameters::Material &material_prm,
                 const double                dt)
        : StateProblem(sheet, body, dt, true)
        , size(size)
        , prm(bending_run(size, mesh, material_prm))
        , material(prm.material)
        , sheet(prm, MPI_COMM_WORLD)
        , body(material, sheet.kinematics, sheet.reference_mapping, mesh.degree)
    {
      sheet.create_mesh();
      make_constraints(bc, true);
      make_constraints(homogeneous, false);
      setup_system();
    }

    /// Newton from the end rotation alone.
    void solve_flow() { solve_velocity(1e-9); }

    using StateProblem<>::state;
    const StripSize                   size;
    const parameters::Run             prm;
    const material::RigidViscoplastic material;

  private:
    state::State<3>            sheet;
    const solver::Assembler<3> body;

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
  };
} // namespace test
