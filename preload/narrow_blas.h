// Narrow BLAS-3 calls sent to BLAS-2. MUMPS's substitutions call GEMM and
// TRSM with one column per right-hand side. Debian 12's OpenBLAS (0.3.21)
// packs the whole matrix operand for them, as for a wide product; only its
// SkylakeX kernels have a small-matrix path. On AVX2 (AMD EPYC, Zen 3) sgemm
// with one column took 5x the time of sgemv at 128-512 rows and strsm 1.5-3x
// that of strsv, and a substitution on the shipped 3-D cup 5.3 ms against
// 3.8 ms (doc/performance.md, "Narrow BLAS calls"). preload/narrow_blas.cc
// is a library of its own, libformsolve_narrow_blas.so, outside the core: it
// defines the Fortran BLAS symbols sgemm_, dgemm_, strsm_ and dtrsm_, and a
// run that loads it first (LD_PRELOAD, as scripts/formsolve-run does) sends
// every caller in the process (MUMPS, deal.II, Trilinos) to them. A call with
// at most two columns goes column by column to GEMV or TRSV; every other call
// passes unchanged to the BLAS library's own function. Without it, every call
// goes to the BLAS library as made.
#pragma once

namespace formsolve
{
  namespace app
  {
    /// The Fortran BLAS GEMM and TRSM of one precision: C = alpha op(A)
    /// op(B) + beta C (transa, transb, m, n, k, alpha, A, lda, B, ldb, beta,
    /// C, ldc), and op(A) X = alpha B or X op(A) = alpha B, B overwritten
    /// (side, uplo, transa, diag, m, n, alpha, A, lda, B, ldb).
    template <typename Real>
    using Gemm = void(const char *,
                      const char *,
                      const int *,
                      const int *,
                      const int *,
                      const Real *,
                      const Real *,
                      const int *,
                      const Real *,
                      const int *,
                      const Real *,
                      Real *,
                      const int *);
    template <typename Real>
    using Trsm = void(const char *,
                      const char *,
                      const char *,
                      const char *,
                      const int *,
                      const int *,
                      const Real *,
                      const Real *,
                      const int *,
                      Real *,
                      const int *);

    /// Whether narrow calls go to BLAS-2 (on until set; for tests).
    void set_narrow_blas(const bool on);
    bool narrow_blas();

    /// Calls sent to BLAS-2 since the start (all four functions): shows
    /// that the definitions are the ones reached.
    unsigned long narrowed_blas_calls();
  } // namespace app
} // namespace formsolve

// The library's definitions, and the count of narrowed calls by a name that
// a run can look up to tell whether the library is loaded.
extern "C" unsigned long                formsolve_narrowed_blas_calls();
extern "C" formsolve::app::Gemm<float>  sgemm_;
extern "C" formsolve::app::Gemm<double> dgemm_;
extern "C" formsolve::app::Trsm<float>  strsm_;
extern "C" formsolve::app::Trsm<double> dtrsm_;
