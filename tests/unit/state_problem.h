// A test's body-only problem on a formsolve State: the constraints bc (with
// the prescribed velocities) and homogeneous (the same lines, zero) that the
// test fills, then setup_system(); Newton from bc with the library's
// assembler and a direct solve. The velocity ends in state.velocity and
// state.velocity_ghost.
#pragma once

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/linear/mumps_solver.h>
#include <formsolve/newton/newton_solver.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/state/state.h>

#include "check.h"
#include "toy_problem.h"

namespace test
{
  class StateProblem : public ToyProblem
  {
  public:
    /// Stores the references only: @p state may be built after this base.
    StateProblem(formsolve::state::State<3>            &state,
                 const formsolve::solver::Assembler<3> &assembler,
                 const double                           time_step,
                 const bool                             symmetric)
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

  protected:
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

    formsolve::state::State<3>            &state;
    const formsolve::solver::Assembler<3> &assembler;
    const double                           time_step; // s, of the assembly
    dealii::AffineConstraints<double>      bc, homogeneous;

  private:
    formsolve::solver::MatrixType  matrix;
    formsolve::solver::VectorType  residual;
    formsolve::solver::MumpsSolver linear;
    double                         scale = 0;
  };
} // namespace test
