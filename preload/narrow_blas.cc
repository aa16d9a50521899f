// The BLAS symbols of preload/narrow_blas.h. The callers are
// Fortran (MUMPS) and C/C++ (deal.II, Trilinos); the hidden string lengths of
// Fortran callers are not read, as the BLAS library's C functions do not
// read them.
#include "narrow_blas.h"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>

extern "C" {
void sgemv_(const char *,
            const int *,
            const int *,
            const float *,
            const float *,
            const int *,
            const float *,
            const int *,
            const float *,
            float *,
            const int *);
void dgemv_(const char *,
            const int *,
            const int *,
            const double *,
            const double *,
            const int *,
            const double *,
            const int *,
            const double *,
            double *,
            const int *);
void strsv_(const char *,
            const char *,
            const char *,
            const int *,
            const float *,
            const int *,
            float *,
            const int *);
void dtrsv_(const char *,
            const char *,
            const char *,
            const int *,
            const double *,
            const int *,
            double *,
            const int *);
void sscal_(const int *, const float *, float *, const int *);
void dscal_(const int *, const double *, double *, const int *);
}

namespace
{
  std::atomic<bool>          enabled{true};
  std::atomic<unsigned long> narrowed{0};
  /// The widest call sent to BLAS-2 (two right-hand sides at once: the
  /// bordered system of solver/mumps_solver_pair.cc).
  constexpr int max_columns = 2;

  template <typename Real>
  using Gemm = formsolve::app::Gemm<Real> *;
  template <typename Real>
  using Trsm = formsolve::app::Trsm<Real> *;

  template <typename Real>
  struct Blas;
  template <>
  struct Blas<float>
  {
    static constexpr const char *gemm_name = "sgemm_", *trsm_name = "strsm_";
    static constexpr auto        gemv = sgemv_;
    static constexpr auto        trsv = strsv_;
    static constexpr auto        scal = sscal_;
  };
  template <>
  struct Blas<double>
  {
    static constexpr const char *gemm_name = "dgemm_", *trsm_name = "dtrsm_";
    static constexpr auto        gemv = dgemv_;
    static constexpr auto        trsv = dtrsv_;
    static constexpr auto        scal = dscal_;
  };

  /// The definition of @p name that this library's own one hides.
  template <typename Function>
  Function next_definition(const char *name)
  {
    void *f = dlsym(RTLD_NEXT, name);
    if (f == nullptr)
      {
        std::fprintf(stderr,
                     "formsolve: no BLAS library defines %s after "
                     "libformsolve_narrow_blas (narrow BLAS calls)\n",
                     name);
        std::abort();
      }
    return reinterpret_cast<Function>(f);
  }

  bool is(const char *c, const char upper)
  {
    return *c == upper || *c == upper - 'A' + 'a';
  }

  bool narrow(const int columns, const int rows)
  {
    return enabled.load(std::memory_order_relaxed) && columns >= 1 &&
           columns <= max_columns && rows >= 1;
  }

  // C = alpha op(A) op(B) + beta C, C m x n.
  template <typename Real>
  void gemm(const char *transa,
            const char *transb,
            const int  *m,
            const int  *n,
            const int  *k,
            const Real *alpha,
            const Real *a,
            const int  *lda,
            const Real *b,
            const int  *ldb,
            const Real *beta,
            Real       *c,
            const int  *ldc)
  {
    static const auto blas = next_definition<Gemm<Real>>(Blas<Real>::gemm_name);
    const bool        plain_a = is(transa, 'N'), plain_b = is(transb, 'N');
    const bool        known = (plain_a || is(transa, 'T') || is(transa, 'C')) &&
                       (plain_b || is(transb, 'T') || is(transb, 'C'));
    if (!known || !narrow(*n, *m) || *k < 1)
      return blas(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
    const int  one = 1, step = plain_b ? 1 : *ldb;
    const Real unit = 1;
    for (int j = 0; j < *n; ++j)
      {
        // Column j of op(B): a column of B, or a row.
        const Real *x = plain_b ? b + std::ptrdiff_t(j) * *ldb : b + j;
        Real       *y = c + std::ptrdiff_t(j) * *ldc;
        // beta = 0: C need not be set on entry (it may hold NaN).
        const Real *beta_j = beta;
        if (*beta == 0)
          {
            std::fill(y, y + *m, Real(0));
            beta_j = &unit;
          }
        if (plain_a)
          Blas<Real>::gemv("N", m, k, alpha, a, lda, x, &step, beta_j, y, &one);
        else
          Blas<Real>::gemv("T", k, m, alpha, a, lda, x, &step, beta_j, y, &one);
      }
    narrowed.fetch_add(1, std::memory_order_relaxed);
  }

  // op(A) X = alpha B (side L), B m x n, overwritten by X.
  template <typename Real>
  void trsm(const char *side,
            const char *uplo,
            const char *transa,
            const char *diag,
            const int  *m,
            const int  *n,
            const Real *alpha,
            const Real *a,
            const int  *lda,
            Real       *b,
            const int  *ldb)
  {
    static const auto blas = next_definition<Trsm<Real>>(Blas<Real>::trsm_name);
    if (!is(side, 'L') || !narrow(*n, *m) || *alpha == 0)
      return blas(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
    const int one = 1;
    for (int j = 0; j < *n; ++j)
      {
        Real *x = b + std::ptrdiff_t(j) * *ldb;
        if (*alpha != 1)
          Blas<Real>::scal(m, alpha, x, &one);
        Blas<Real>::trsv(uplo, transa, diag, m, a, lda, x, &one);
      }
    narrowed.fetch_add(1, std::memory_order_relaxed);
  }
} // namespace

extern "C" {
void sgemm_(const char  *transa,
            const char  *transb,
            const int   *m,
            const int   *n,
            const int   *k,
            const float *alpha,
            const float *a,
            const int   *lda,
            const float *b,
            const int   *ldb,
            const float *beta,
            float       *c,
            const int   *ldc)
{
  gemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

void dgemm_(const char   *transa,
            const char   *transb,
            const int    *m,
            const int    *n,
            const int    *k,
            const double *alpha,
            const double *a,
            const int    *lda,
            const double *b,
            const int    *ldb,
            const double *beta,
            double       *c,
            const int    *ldc)
{
  gemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

void strsm_(const char  *side,
            const char  *uplo,
            const char  *transa,
            const char  *diag,
            const int   *m,
            const int   *n,
            const float *alpha,
            const float *a,
            const int   *lda,
            float       *b,
            const int   *ldb)
{
  trsm(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
}

void dtrsm_(const char   *side,
            const char   *uplo,
            const char   *transa,
            const char   *diag,
            const int    *m,
            const int    *n,
            const double *alpha,
            const double *a,
            const int    *lda,
            double       *b,
            const int    *ldb)
{
  trsm(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
}
}

namespace formsolve
{
  namespace app
  {
    void set_narrow_blas(const bool on)
    {
      enabled = on;
    }

    bool narrow_blas()
    {
      return enabled;
    }

    unsigned long narrowed_blas_calls()
    {
      return narrowed;
    }
  } // namespace app
} // namespace formsolve

unsigned long formsolve_narrowed_blas_calls()
{
  return narrowed;
}
