// The sheet as one operator of the step: its residual and tangent at a
// velocity, through the kinematics and the material law (the assembler,
// doc/theory.md sections 3-5), with the tangent chosen by Nonlinear
// solver/Tangent. For the stress-velocity tangent (eq. 4b) it keeps the dual
// directions: those of the accepted iterate, about which every trial is
// linearised, and those of the last trial.
#pragma once

#include <formsolve/forming/assembler.h>
#include <formsolve/forming/cell_scatter.h>
#include <formsolve/forming/dual_stress.h>
#include <formsolve/newton/nonlinear_problem.h>
#include <formsolve/state/state.h>

#include <array>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class BodyOperator
    {
    public:
      BodyOperator(const Assembler<dim>              &assembler,
                   const parameters::NonlinearSolver &prm);

      /// Frees the cell map and the dual directions (before a new system is
      /// built, so that the old and the new never coexist).
      void clear();
      /// A new mesh: the cell map of @p matrix, the dual directions' storage.
      void reinit(const state::State<dim> &state, const MatrixType &matrix);
      /// A step begins from the secant tangent: the last step's
      /// linearisation point lies in another configuration (and a resumed
      /// run must iterate as the uninterrupted one).
      void begin_step()
      {
        dual.reset();
        frames.clear();
      }

      /// The body residual r_b at the ghosted velocity @p v (and its tangent
      /// K_b into @p matrix if not null), in the state's current
      /// configuration, for a step of @p dt. @p kind exact: the derivative
      /// of r_b, the dual directions restarted at the accepted iterate.
      /// Returns the force scale of |r| (the element internal forces).
      double evaluate(const state::State<dim> &state,
                      const VectorType        &v,
                      const double             dt,
                      const Linearisation      kind,
                      MatrixType              *matrix,
                      VectorType              &residual);
      /// As evaluate(), for the iterate accepted last, whose tangent comes
      /// after its acceptance: linearised about the iterate before it, as
      /// an assembly before the acceptance would have been.
      double evaluate_accepted(const state::State<dim> &state,
                               const VectorType        &v,
                               const double             dt,
                               const Linearisation      kind,
                               MatrixType              *matrix,
                               VectorType              &residual);

      /// The last trial becomes the linearisation point; with @p count,
      /// first the rigid-plastic transitions for the log (collective).
      void accept(const MPI_Comm comm, const bool count);

      /// The point frames of the step's configuration, once an evaluation
      /// has computed them (else nullptr).
      const material::PointFrames<dim> *point_frames() const
      {
        return frames.ready() ? &frames : nullptr;
      }

      /// Whether the tangent is the stress-velocity one.
      bool stress_velocity() const { return use_dual; }
      /// {rigid points, to rigid, to plastic} at the last accept() counted.
      const std::array<unsigned int, 3> &rigid_counts() const { return counts; }

    private:
      const Assembler<dim>       &assembler;
      const bool                  use_dual;
      CellScatter<dim>            scatter; // positions of cell tangents
      DualStress                  dual;
      material::PointFrames<dim>  frames; // of the step's configuration
      std::array<unsigned int, 3> counts{{0, 0, 0}};
    };
  } // namespace solver
} // namespace formsolve
