// A test's body-only problem on a formsolve State: the constraints bc (with
// the prescribed velocities) and homogeneous (the same lines, zero) that the
// test fills, then setup_system(); Newton from bc with the library's
// assembler and a direct solve. The velocity ends in state.velocity and
// state.velocity_ghost.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/linear/mumps_solver.h>
#include <formsolve/material/hill_orientation.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/newton/newton_solver.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/state/state.h>

#include "check.h"
#include "toy_problem.h"

#include <map>
#include <set>

namespace test
{
  /// The rate of deformation and the flow stress at the first quadrature
  /// point of this rank's first cell (for a homogeneous flow: any point's).
  template <int dim>
  std::pair<dealii::SymmetricTensor<2, 3>, double>
  first_point(const formsolve::state::State<dim>           &state,
              const formsolve::material::RigidViscoplastic &material,
              const double                                  dt)
  {
    using namespace formsolve;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const dealii::QGauss<dim>                  rule(2);
          model::CellKinematics<dim>                 k(state.kinematics,
                                       *state.mapping,
                                       state.fe,
                                       rule,
                                       dealii::update_jacobians,
                                       &state.reference_mapping);
          material::HillOrientation<dim>             o(material);
          std::vector<dealii::SymmetricTensor<2, 3>> D;
          k.reinit(cell);
          o.reinit(k);
          k.rates(state.velocity_ghost, D);
          return {D[0],
                  material.evaluate(D[0], 0, dt, false, o.map(0)).flow_stress};
        }
    return {dealii::SymmetricTensor<2, 3>(), 0.};
  }

  /// A plane-strain strip L x T of width W with no tools: the section
  /// x >= 0 of it on @p mesh.
  inline formsolve::parameters::Run
  plane_strain_strip(const double                       L,
                     const double                       W,
                     const double                       T,
                     const formsolve::parameters::Mesh &mesh)
  {
    formsolve::parameters::Run prm;
    prm.geometry.model        = formsolve::model::Model::plane_strain;
    prm.geometry.blank_shape  = formsolve::parameters::BlankShape::rectangle;
    prm.geometry.blank_length = L;
    prm.geometry.blank_width  = W;
    prm.geometry.thickness    = T;
    prm.mesh                  = mesh;
    prm.tools.die.enabled     = false;
    prm.tools.blank_holder.enabled = false;
    return prm;
  }

  template <int dim = 3>
  class StateProblem : public ToyProblem
  {
  public:
    /// Stores the references only: @p state may be built after this base.
    StateProblem(formsolve::state::State<dim>            &state,
                 const formsolve::solver::Assembler<dim> &assembler,
                 const double                             time_step,
                 const bool                               symmetric)
        : state(state)
        , assembler(assembler)
        , time_step(time_step)
        , linear(formsolve::parameters::LinearSolver(), symmetric)
    {}

    /// Newton from bc to @p tolerance (residual and correction).
    void solve_velocity(const double tolerance)
    {
      using namespace formsolve;
      bc.distribute(state.velocity);
      parameters::NonlinearSolver p;
      p.residual_tolerance    = tolerance;
      p.correction_tolerance  = tolerance;
      p.max_line_search_steps = 8;
      const auto r            = solve_from(
        solver::NewtonSolver(p, dealii::ConditionalOStream(std::cout, false)),
        state.velocity);
      close("Newton converged", r.converged, 1, 0);
      state.velocity_ghost = state.velocity;
    }

    double assemble(const VectorType &v, const bool newton) override
    {
      state.velocity_ghost = v;
      scale                = assembler.assemble_body(state.dof_handler,
                                      *state.mapping,
                                      homogeneous,
                                      state.velocity_ghost,
                                      state.history,
                                      time_step,
                                      newton,
                                      &matrix,
                                      residual);
      return residual.l2_norm();
    }
    double force_scale() const override { return scale; }
    double directional_derivative(const VectorType &dv) const override
    {
      return residual * dv;
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      VectorType rhs(residual);
      rhs *= -1.;
      const auto its = linear.solve(matrix, dv, rhs);
      homogeneous.distribute(dv);
      return its;
    }

    /// The residual without the test's constraints (the State's symmetry
    /// and hanging-node lines only) at the current velocity: at a converged
    /// flow, the forces on the prescribed DoFs.
    formsolve::solver::VectorType unconstrained_residual() const
    {
      dealii::AffineConstraints<double> none;
      none.reinit(state.relevant);
      none.merge(state.constraints);
      none.close();
      formsolve::solver::VectorType r(state.owned, state.comm);
      assembler.assemble_body(state.dof_handler,
                              *state.mapping,
                              none,
                              state.velocity_ghost,
                              state.history,
                              time_step,
                              false,
                              nullptr,
                              r);
      return r;
    }

    /// The sum of the unconstrained residual's component-0 entries at the
    /// owned DoFs whose support point is @p at (the x force on a face).
    template <class Where>
    double x_force(const Where &at) const
    {
      const auto r = unconstrained_residual();
      std::map<dealii::types::global_dof_index, dealii::Point<dim>> points;
      dealii::DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                                   state.dof_handler,
                                                   points);
      std::set<dealii::types::global_dof_index>    face;
      std::vector<dealii::types::global_dof_index> dofs(
        state.fe.n_dofs_per_cell());
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (state.fe.system_to_component_index(i).first == 0 &&
                  state.owned.is_element(dofs[i]) && at(points[dofs[i]]))
                face.insert(dofs[i]);
          }
      double force = 0;
      for (const auto i : face)
        force += r[i];
      return dealii::Utilities::MPI::sum(force, state.comm);
    }

  protected:
    /// bc and homogeneous from the State's constraints and the velocities
    /// @p prescribe(point, component, value) sets (true: the DoF gets
    /// value in bc, 0 in homogeneous); then closes both and sets up the
    /// system.
    template <class Prescribe>
    void prescribe_velocities(const Prescribe &prescribe)
    {
      std::map<dealii::types::global_dof_index, dealii::Point<dim>> points;
      dealii::DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                                   state.dof_handler,
                                                   points);
      for (auto *c : {&bc, &homogeneous})
        {
          c->clear();
          c->reinit(state.relevant);
          c->merge(state.constraints);
        }
      std::vector<dealii::types::global_dof_index> dofs(
        state.fe.n_dofs_per_cell());
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                double value = 0;
                if (!prescribe(points[dofs[i]],
                               state.fe.system_to_component_index(i).first,
                               value))
                  continue;
                for (auto *c : {&bc, &homogeneous})
                  if (!c->is_constrained(dofs[i]))
                    {
                      c->add_line(dofs[i]);
                      c->set_inhomogeneity(dofs[i], c == &bc ? value : 0.);
                    }
              }
          }
      bc.close();
      homogeneous.close();
      setup_system();
    }

    /// The matrix and residual for the closed constraints.
    void setup_system()
    {
      dealii::DynamicSparsityPattern dsp(state.relevant);
      dealii::DoFTools::make_sparsity_pattern(state.dof_handler,
                                              dsp,
                                              homogeneous,
                                              false);
      dealii::SparsityTools::distribute_sparsity_pattern(dsp,
                                                         state.owned,
                                                         state.comm,
                                                         state.relevant);
      matrix.reinit(state.owned, state.owned, dsp, state.comm);
      residual.reinit(state.owned, state.comm);
    }

    formsolve::state::State<dim>            &state;
    const formsolve::solver::Assembler<dim> &assembler;
    const double                             time_step; // s, of the assembly
    dealii::AffineConstraints<double>        bc, homogeneous;

  private:
    formsolve::solver::MatrixType  matrix;
    formsolve::solver::VectorType  residual;
    formsolve::solver::MumpsSolver linear;
    double                         scale = 0;
  };
} // namespace test
