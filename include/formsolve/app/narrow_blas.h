// Narrow BLAS-3 calls sent to BLAS-2. MUMPS's substitutions call GEMM and
// TRSM with one column per right-hand side. Debian 12's OpenBLAS (0.3.21)
// packs the whole matrix operand for them, as for a wide product; only its
// SkylakeX kernels have a small-matrix path. On AVX2 (AMD EPYC, Zen 3) sgemm
// with one column took 5x the time of sgemv at 128-512 rows and strsm 1.5-3x
// that of strsv, and a substitution on the shipped 3-D cup 5.3 ms against
// 3.8 ms (doc/performance.md, "Narrow BLAS calls"). source/app/narrow_blas.cc
// defines the Fortran BLAS symbols sgemm_, dgemm_, strsm_ and dtrsm_: the core
// library is the executable's first library, so its definitions are the ones
// every caller in the process (MUMPS, deal.II, Trilinos) reaches. A call with
// at most two columns goes column by column to GEMV or TRSV; every other call
// passes unchanged to the BLAS library's own function.
#pragma once

namespace formsolve
{
  namespace app
  {
    /// Whether narrow calls go to BLAS-2 (Linear solver/Narrow BLAS calls;
    /// on until set).
    void set_narrow_blas(const bool on);
    bool narrow_blas();

    /// Calls sent to BLAS-2 since the start (all four functions): shows
    /// that the definitions are the ones reached.
    unsigned long narrowed_blas_calls();
  } // namespace app
} // namespace formsolve
