// When the linear solver may try its last factors on a new matrix (Linear
// solver/Reuse velocity change): only within one Newton solve, and only while
// the velocity the matrix was assembled at lies close to that of the
// factorised matrix. Early iterations of a step change the tangent (strain
// rates, contact status) too much for GMRES to converge on old factors, and
// each failed attempt costs Reuse factorisation iterations substitutions.
#pragma once
#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>

namespace formsolve
{
  namespace solver
  {
    class FactorReuse
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// @p max_change: the largest |v - v_f|/|v| tried (0: always try,
      /// also across solves and steps).
      explicit FactorReuse(const double max_change)
          : max_change(max_change)
      {}
      /// Vectors for the current mesh; no factors yet.
      void reinit(const dealii::IndexSet &owned, const MPI_Comm comm);
      /// A Newton solve begins: the factors of earlier solves are not tried.
      void begin_solve() { factors_valid = false; }
      /// The matrix was (re)assembled at velocity @p v.
      void assembled_at(const VectorType &v) { matrix_point = v; }
      /// Whether to try the last factors on the current matrix (collective).
      bool may_reuse() const;
      /// The current matrix was factorised.
      void factorised();

    private:
      const double max_change;
      VectorType   matrix_point, factor_point;
      bool         factors_valid = false;
    };
  } // namespace solver
} // namespace formsolve
