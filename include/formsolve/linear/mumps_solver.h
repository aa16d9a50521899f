// The MUMPS back end of LinearSolver (solver/linear_solver.h): formsolve's
// MUMPS instance (solver/mumps_direct.h) with its analysis kept per sparsity
// pattern, exact or approximate factors (single precision, block low-rank,
// the symmetric part of an unsymmetric tangent), and the last factors reused
// as the preconditioner of flexible GMRES on later matrices (Reuse
// factorisation iterations).
#pragma once

#include <formsolve/linear/linear_solver.h>
#include <formsolve/linear/mumps_direct.h>

#include <memory>

namespace formsolve
{
  namespace solver
  {
    class MumpsSolver : public LinearSolver
    {
    public:
      MumpsSolver(const parameters::LinearSolver &p, const bool symmetric);

      unsigned int solve(const Matrix &A,
                         Vector       &x,
                         const Vector &b,
                         const bool    may_reuse = true) override;
      /// Each application of the factors serves both right-hand sides in one
      /// pass over them (the substitution reads the whole factor from
      /// memory, and that is most of its cost).
      unsigned int solve_pair(const Matrix &A,
                              Vector       &x,
                              const Vector &b,
                              Vector       &y,
                              const Vector &c,
                              const bool    may_reuse = true) override;
      void set_forcing(const double tolerance) override { forcing = tolerance; }
      void time_phases(dealii::TimerOutput &t) override { timer = &t; }
      unsigned long factorisations() const override { return n_factorisations; }
      /// MUMPS 5.5 cannot free the factors and keep the analysis (it refuses
      /// JOB = -4): the next solve analyses again.
      void   release_factors() override;
      double factorisation_memory_mb() const override;
      double factor_entries() const override;

    private:
      /// GMRES iterations allowed with each kind of approximate factors.
      static constexpr unsigned int single_precision_iterations = 20;
      static constexpr unsigned int symmetric_part_iterations   = 30;

      /// A is the analysed matrix object with its sparsity unchanged.
      bool has_factorised_pattern(const Matrix &A) const;
      /// The analysis of @p A's pattern unless it is the factorised one.
      void analyse_if_new(const Matrix &A);
      /// Numeric factorisation of the last matrix's current values.
      void factorise_current();
      /// The solve with A factorised (analysed first if its pattern is new).
      unsigned int factorise_new(const Matrix &A, Vector &x, const Vector &b);
      /// The factors are those of the matrix, in double precision: one
      /// substitution solves.
      bool exact_factors() const;
      /// How many GMRES iterations the current approximate factors may take.
      unsigned int approximate_factors_limit() const;
      [[noreturn]] void
      approximate_factors_failed(const unsigned int limit) const;
      /// x = A^-1 b with the factors of A's current values: one
      /// substitution, or GMRES when they are approximate.
      unsigned int apply_current_factors(Vector &x, const Vector &b);
      unsigned int apply_current_factors(Vector       &x,
                                         const Vector &b,
                                         Vector       &y,
                                         const Vector &c);
      void         substitute(Vector &x, const Vector &b);
      void substitute(Vector &x, const Vector &b, Vector &y, const Vector &c);
      /// GMRES on @p A preconditioned by the stored factors (an older
      /// factorisation, or approximate factors), to the reuse tolerance;
      /// false if it does not converge within @p max_iterations.
      bool         gmres_with_factors(const Matrix      &A,
                                      Vector            &x,
                                      const Vector      &b,
                                      const unsigned int max_iterations,
                                      unsigned int      &iterations);
      unsigned int gmres_pair_with_factors(const Matrix      &A,
                                           Vector            &x,
                                           const Vector      &b,
                                           Vector            &y,
                                           const Vector      &c,
                                           const unsigned int max_iterations,
                                           bool (&converged)[2]);

      parameters::LinearSolver     prm;
      const bool                   symmetric;
      std::unique_ptr<MumpsDirect> mumps;
      dealii::TimerOutput         *timer             = nullptr;
      const Matrix                *last_matrix       = nullptr;
      const void                  *factorised_matrix = nullptr;
      unsigned long long           factorised_nnz    = 0;
      unsigned long                n_factorisations  = 0;
      double                       forcing           = 0;
      bool                         try_reuse         = true;
      /// The factorisation is that of last_matrix's current values (else it
      /// is an older one, used as a preconditioner).
      bool factors_current = false;
    };
  } // namespace solver
} // namespace formsolve
