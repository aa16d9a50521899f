// The penalty side of FormingSystem: the factors at accepted iterates
// (update, strict correction, the estimate at convergence) and the contact
// terms they make. The body tangent an adaptive estimate reads is the matrix
// with the contact stiffness taken back out; a deferred tangent is assembled
// first where the estimate needs it.
#include <formsolve/contact/contact_assembly.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/solver/forming_system.h>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    void FormingSystem<dim>::end_solve()
    {
      if (!strategy.needs_system())
        return;
      if (tangent_deferred)
        {
          // The matrix is of the iterate before; the next solve assembles
          // anew, and only a strategy that reads it needs the tangent.
          if (!strategy.reads_converged_system())
            return;
          complete_tangent();
        }
      // The body tangent for the strategy; the next solve assembles anew.
      remove_contact_stiffness();
      TimerOutput::Scope t(timer, "penalty estimate");
      strategy.converged(
        state.contact_set,
        state.tools,
        contact::SystemView{&body_residual, &matrix, &state.constraints, dt},
        state.contact_state);
    }

    template <int dim>
    void FormingSystem<dim>::estimate_penalty(const VectorType &r_b,
                                              const MatrixType &K_b)
    {
      TimerOutput::Scope t(timer, "penalty estimate");
      strategy.estimate(state.contact_set,
                        state.tools,
                        contact::SystemView{&r_b,
                                            &K_b,
                                            &state.constraints,
                                            dt,
                                            predictor_iterate},
                        state.contact_state,
                        epsilon);
    }

    template <int dim>
    void FormingSystem<dim>::contact_terms(MatrixType  *into_matrix,
                                           VectorType  *into_residual,
                                           const double sign)
    {
      TimerOutput::Scope t(timer, "assembly: contact terms");
      contact::add_contact_terms(state.contact_set,
                                 epsilon,
                                 state.tools,
                                 prm.contact.regularisation_velocity,
                                 dt,
                                 last_newton,
                                 prm.nonlinear.symmetrise_friction,
                                 state.constraints,
                                 into_matrix,
                                 into_residual,
                                 sign);
    }

    template <int dim>
    void FormingSystem<dim>::add_contact_terms(const bool with_matrix)
    {
      contact_terms(with_matrix ? &matrix : nullptr, &residual, 1.);
      if (with_matrix)
        contact_in_matrix = true;
      if (holder_controlled())
        holder.assemble(state.contact_set,
                        epsilon,
                        state.tools,
                        prm.contact.regularisation_velocity,
                        dt,
                        last_newton,
                        state.constraints,
                        state.holder.target);
    }

    template <int dim>
    void FormingSystem<dim>::remove_contact_stiffness()
    {
      // The matrix holds K_b + K_c of the last assembly: the pairs, factors,
      // tools and tangent type it was made with are still those of the
      // state (no search and no estimate since).
      Assert(contact_in_matrix, ExcInternalError());
      contact_terms(&matrix, nullptr, -1.);
      contact_in_matrix = false;
    }

    template <int dim>
    double FormingSystem<dim>::update_penalty()
    {
      if (!strategy.needs_system())
        return -1;
      if (tangent_deferred)
        {
          // Held factors: the residual of the trial is already this one.
          if (strategy.holds_factors(state.contact_set,
                                     state.tools,
                                     state.contact_state,
                                     predictor_iterate,
                                     state.comm))
            return -1;
          complete_tangent();
        }
      remove_contact_stiffness();
      estimate_penalty(body_residual, matrix);
      // Newton estimates here once per accepted iterate, the predictor first.
      predictor_iterate = false;
      residual          = body_residual;
      // The copy leaves the vector in 'insert' mode; settle it on every rank
      // now, before ranks with and without contact pairs start adding.
      residual.compress(VectorOperation::insert);
      add_contact_terms();
      return residual.l2_norm();
    }

    template <int dim>
    double FormingSystem<dim>::correct_penalty()
    {
      if (!strategy.needs_system() || !strategy.tighten(state.contact_set,
                                                        state.tools,
                                                        state.contact_state,
                                                        state.comm))
        return -1;
      // Estimate again with the new scales (not frozen) at this iterate.
      strategy.begin_solve();
      complete_tangent();
      return update_penalty();
    }

#define INSTANTIATE(dim)                                                    \
  template void   FormingSystem<dim>::end_solve();                          \
  template void   FormingSystem<dim>::estimate_penalty(const VectorType &,  \
                                                     const MatrixType &); \
  template void   FormingSystem<dim>::contact_terms(MatrixType *,           \
                                                  VectorType *,           \
                                                  const double);          \
  template void   FormingSystem<dim>::add_contact_terms(const bool);        \
  template void   FormingSystem<dim>::remove_contact_stiffness();           \
  template double FormingSystem<dim>::update_penalty();                     \
  template double FormingSystem<dim>::correct_penalty();
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
