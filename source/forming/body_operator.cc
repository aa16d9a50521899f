#include <deal.II/base/mpi.h>

#include <formsolve/forming/body_operator.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    BodyOperator<dim>::BodyOperator(const Assembler<dim> &assembler,
                                    const parameters::NonlinearSolver &prm)
        : assembler(assembler)
        , use_dual(prm.tangent == parameters::Tangent::stress_velocity)
    {}

    template <int dim>
    void BodyOperator<dim>::clear()
    {
      scatter = CellScatter<dim>();
      dual    = DualStress();
      frames  = material::PointFrames<dim>();
    }

    template <int dim>
    void BodyOperator<dim>::reinit(const state::State<dim> &state,
                                   const MatrixType        &matrix)
    {
      scatter.reinit(state.dof_handler, state.constraints, matrix);
      dual.reinit(state.dof_handler.get_triangulation().n_active_cells(),
                  assembler.quadrature().size(),
                  assembler.law().non_quadratic() != nullptr);
      frames.clear();
    }

    template <int dim>
    double BodyOperator<dim>::evaluate(const state::State<dim> &state,
                                       const VectorType        &v,
                                       const double             dt,
                                       const Linearisation      kind,
                                       MatrixType              *matrix,
                                       VectorType              &residual)
    {
      if (kind == Linearisation::exact)
        dual.restart(assembler.cutoff_rate(), assembler.smooth_rigid_zone());
      // The mesh stands still within a step: its frames once.
      if (!frames.ready())
        frames.compute(assembler.law(),
                       state.kinematics,
                       state.dof_handler,
                       *state.mapping,
                       state.reference_mapping,
                       assembler.quadrature());
      return assembler.assemble_body(state.dof_handler,
                                     *state.mapping,
                                     state.constraints,
                                     v,
                                     state.history,
                                     dt,
                                     kind != Linearisation::secant,
                                     matrix,
                                     residual,
                                     use_dual && kind != Linearisation::exact
                                       ? &dual
                                       : nullptr,
                                     &scatter,
                                     &frames);
    }

    template <int dim>
    double BodyOperator<dim>::evaluate_accepted(const state::State<dim> &state,
                                                const VectorType        &v,
                                                const double             dt,
                                                const Linearisation      kind,
                                                MatrixType              *matrix,
                                                VectorType &residual)
    {
      if (use_dual)
        dual.revert();
      const double scale = evaluate(state, v, dt, kind, matrix, residual);
      if (use_dual)
        dual.accept();
      return scale;
    }

    template <int dim>
    void BodyOperator<dim>::accept(const MPI_Comm comm, const bool count)
    {
      if (!use_dual)
        return;
      if (count)
        {
          // Rigid-plastic transitions: a category of hard steps
          // (doc/convergence.md).
          counts         = dual.rigid_transitions(assembler.cutoff_rate());
          const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                         counts.data(),
                                         3,
                                         MPI_UNSIGNED,
                                         MPI_SUM,
                                         comm);
          AssertThrowMPI(ierr);
        }
      dual.accept();
    }

#define INSTANTIATE(dim) template class BodyOperator<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
