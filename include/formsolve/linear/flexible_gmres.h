// Right-preconditioned flexible GMRES (Saad 1993) for the solves with stored
// factors (solver/linear_solver.cc). It keeps z_j = P^-1 v_j and forms
// x = x0 + sum_j y_j z_j, so that b - A x is the residual the iteration
// estimated, whatever P^-1 does to each vector (single-precision or older
// factors). deal.II 9.4's SolverGMRES forms x = x0 + P^-1 (V y) with one more
// application of P^-1: with single-precision factors that application alone
// leaves |b - A x| at 1e-3 |b| and more, far above the tolerance it reported
// (doc/performance.md, "Flexible GMRES"). Its SolverFGMRES tests convergence
// one column late, which costs one application per solve as well.
//
// The iteration is a class that asks for one preconditioned vector at a
// time, so that two solves with the same preconditioner can run side by
// side and have P^-1 applied to both vectors in one call (one pass over the
// factors for two right-hand sides: flexible_gmres_pair).
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    struct FlexibleGmresResult
    {
      /// Preconditioner applications (= Krylov columns) used.
      unsigned int iterations = 0;
      /// |b - A x| at return (the iteration's estimate, which is the true
      /// residual up to round-off in double precision).
      double residual  = 0;
      bool   converged = false;
    };

    /// One flexible GMRES solve of A x = b from the initial @p x until
    /// |b - A x| <= @p tolerance (absolute), within @p max_iterations
    /// preconditioner applications; restarts every @p max_basis columns.
    /// While !finished(): write P^-1 direction() into preconditioned(), then
    /// advance(). @p x holds the last iterate also when it does not
    /// converge; @p x and @p b must outlive the object.
    class FlexibleGmres
    {
    public:
      using Vector   = dealii::TrilinosWrappers::MPI::Vector;
      using Operator = std::function<void(Vector &, const Vector &)>;

      FlexibleGmres(const Operator    &operator_vmult,
                    Vector            &x,
                    const Vector      &b,
                    const double       tolerance,
                    const unsigned int max_iterations,
                    const unsigned int max_basis = 100);

      bool finished() const { return done; }
      /// The vector to precondition next.
      const Vector &direction() const { return v[k]; }
      /// Where P^-1 direction() goes (laid out as b).
      Vector &preconditioned();
      /// One iteration with the vector written into preconditioned().
      void advance();

      FlexibleGmresResult result() const;

    private:
      const Operator      vmult;
      Vector             &x;
      const Vector       &b;
      const double        tolerance;
      const unsigned int  max_iterations;
      const unsigned int  m;
      std::vector<Vector> v, z;
      // Hessenberg columns after the Givens rotations (upper triangle R),
      // the rotations, and the rotated right-hand side g.
      std::vector<std::vector<double>> h;
      std::vector<double>              cs, sn, g;
      Vector                           w;
      unsigned int                     k          = 0; // columns this cycle
      unsigned int                     iterations = 0;
      double                           residual   = 0;
      bool                             done       = false;

      /// A cycle from the residual in w, or the end.
      void start_cycle();
      /// x += Z y; then converged, or the true residual and a restart.
      void finish_cycle();
    };

    /// Solves A x = b with FlexibleGmres, applying @p precondition.
    FlexibleGmresResult
    flexible_gmres(const FlexibleGmres::Operator               &operator_vmult,
                   const FlexibleGmres::Operator               &precondition,
                   dealii::TrilinosWrappers::MPI::Vector       &x,
                   const dealii::TrilinosWrappers::MPI::Vector &b,
                   const double                                 tolerance,
                   const unsigned int                           max_iterations,
                   const unsigned int max_basis = 100);

    /// P^-1 applied to two vectors at once: (dst0, src0, dst1, src1).
    using PairPreconditioner =
      std::function<void(dealii::TrilinosWrappers::MPI::Vector &,
                         const dealii::TrilinosWrappers::MPI::Vector &,
                         dealii::TrilinosWrappers::MPI::Vector &,
                         const dealii::TrilinosWrappers::MPI::Vector &)>;

    /// Two FlexibleGmres solves with the same operator and preconditioner,
    /// side by side: while both run, their vectors are preconditioned
    /// together by @p precondition_pair; the one left runs with
    /// @p precondition. Each solve computes what flexible_gmres() computes
    /// for it alone (up to the round-off of the paired application).
    std::vector<FlexibleGmresResult>
    flexible_gmres_pair(const FlexibleGmres::Operator &operator_vmult,
                        const FlexibleGmres::Operator &precondition,
                        const PairPreconditioner      &precondition_pair,
                        dealii::TrilinosWrappers::MPI::Vector       &x0,
                        const dealii::TrilinosWrappers::MPI::Vector &b0,
                        const double                                 tolerance0,
                        const unsigned int                     max_iterations0,
                        dealii::TrilinosWrappers::MPI::Vector &x1,
                        const dealii::TrilinosWrappers::MPI::Vector &b1,
                        const double                                 tolerance1,
                        const unsigned int max_iterations1);
  } // namespace solver
} // namespace formsolve
