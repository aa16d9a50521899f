#include <formsolve/linear/factor_reuse.h>

namespace formsolve
{
  namespace solver
  {
    void FactorReuse::reinit(const dealii::IndexSet &owned, const MPI_Comm comm)
    {
      matrix_point.reinit(owned, comm);
      factor_point.reinit(owned, comm);
      factors_valid = false;
    }

    bool FactorReuse::may_reuse() const
    {
      if (max_change == 0)
        return true;
      if (!factors_valid)
        return false;
      // The tangent follows the velocity: close velocities, close matrices,
      // and GMRES on the old factors converges in few iterations.
      VectorType change(matrix_point);
      change -= factor_point;
      return change.l2_norm() <= max_change * matrix_point.l2_norm();
    }

    void FactorReuse::factorised()
    {
      factor_point  = matrix_point;
      factors_valid = true;
    }
  } // namespace solver
} // namespace formsolve
