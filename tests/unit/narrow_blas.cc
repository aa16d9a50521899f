// Narrow BLAS calls (preload/narrow_blas.cc): sgemm_, dgemm_, strsm_ and dtrsm_
// with one or two columns, sent to GEMV and TRSV, must give what the BLAS
// library's own functions give, for every transpose, both triangles, unit
// and non-unit diagonals, alpha and beta (beta = 0 over a C that holds NaN),
// and row strides; a switched-off or wide call must reach the library's
// function unchanged (bitwise). MUMPS's solve must reach these definitions
// (the count of narrowed calls grows), and its solution must not change
// beyond round-off.
#include "narrow_blas.h"

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/linear/mumps_direct.h>

#include "check.h"
#include "penalty_operator.h"
#include <dlfcn.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
  template <typename Real>
  using Gemm = formsolve::app::Gemm<Real> *;
  template <typename Real>
  using Trsm = formsolve::app::Trsm<Real> *;

  /// The BLAS library's own function, from the library itself.
  void *library_function(const char *name)
  {
    static void *blas = dlopen("libblas.so.3", RTLD_NOW | RTLD_LOCAL);
    return blas ? dlsym(blas, name) : nullptr;
  }

  template <typename Real>
  std::vector<Real> values(const std::size_t n, const double seed)
  {
    std::vector<Real> v(n);
    for (std::size_t i = 0; i < n; ++i)
      v[i] = Real(std::sin(seed * (i + 1)) + 0.1 * std::cos(3. * i));
    return v;
  }

  template <typename Real>
  double max_relative_difference(const std::vector<Real> &a,
                                 const std::vector<Real> &b)
  {
    double diff = 0, size = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        if (std::isnan(double(a[i])) != std::isnan(double(b[i])))
          return std::numeric_limits<double>::infinity();
        diff = std::max(diff, std::abs(double(a[i]) - double(b[i])));
        size = std::max(size, std::abs(double(b[i])));
      }
    return diff / std::max(size, 1e-300);
  }

  /// Runs @p ours and @p library (each writes its result), then checks
  /// that ours was narrowed exactly when the call has n <= 2 columns and
  /// that the results agree (to @p tol where narrowed, exactly otherwise).
  template <typename Real, typename Ours, typename Library>
  void compare(const std::string       &what,
               const int                n,
               const double             tol,
               const Ours              &ours,
               const Library           &library,
               const std::vector<Real> &result,
               const std::vector<Real> &reference)
  {
    const unsigned long before = formsolve::app::narrowed_blas_calls();
    ours();
    const bool narrowed = formsolve::app::narrowed_blas_calls() > before;
    library();
    test::close(what + ": narrowed exactly when n <= 2", narrowed, n <= 2, 0);
    test::close(what + ": the library's result",
                max_relative_difference(result, reference),
                0,
                n <= 2 ? tol : 0.);
  }

  template <typename Real>
  void check_gemm(Gemm<Real> ours, Gemm<Real> library, const double tol)
  {
    const std::string kind = sizeof(Real) == 4 ? "sgemm" : "dgemm";
    const int         m = 37, k = 23, lda = 41, ldb = 29, ldc = 40;
    const auto        a = values<Real>(lda * 41, 0.37);
    for (const char *ta : {"N", "T", "c"})
      for (const char *tb : {"N", "t"})
        for (const int n : {1, 2, 3})
          for (const double beta : {0., 1., -0.5})
            {
              const Real al = 1.5, be = beta;
              const auto b = values<Real>(ldb * 41, 0.91);
              auto       c = values<Real>(ldc * n, 0.13), reference = c;
              if (beta == 0)
                c[1] = reference[1] = std::numeric_limits<Real>::quiet_NaN();
              const auto call = [&](Gemm<Real> f, Real *into) {
                f(ta,
                  tb,
                  &m,
                  &n,
                  &k,
                  &al,
                  a.data(),
                  &lda,
                  b.data(),
                  &ldb,
                  &be,
                  into,
                  &ldc);
              };
              compare(
                kind + " " + ta + tb + " n=" + std::to_string(n) +
                  " beta=" + std::to_string(beta),
                n,
                tol,
                [&]() { call(ours, c.data()); },
                [&]() { call(library, reference.data()); },
                c,
                reference);
            }
  }

  template <typename Real>
  void check_trsm(Trsm<Real> ours, Trsm<Real> library, const double tol)
  {
    const std::string kind = sizeof(Real) == 4 ? "strsm" : "dtrsm";
    const int         m = 31, lda = 33, ldb = 35;
    auto              a = values<Real>(lda * m, 0.29);
    for (int i = 0; i < m; ++i)
      a[i + i * lda] = 4 + i % 3; // well conditioned
    for (const char *uplo : {"U", "l"})
      for (const char *trans : {"N", "T"})
        for (const char *diag : {"N", "U"})
          for (const int n : {1, 2, 3})
            for (const double alpha : {1., 2.5})
              {
                const Real al = alpha;
                auto       b = values<Real>(ldb * n, 0.71), reference = b;
                const auto call = [&](Trsm<Real> f, Real *into) {
                  f("L",
                    uplo,
                    trans,
                    diag,
                    &m,
                    &n,
                    &al,
                    a.data(),
                    &lda,
                    into,
                    &ldb);
                };
                compare(
                  kind + " " + uplo + trans + diag + " n=" + std::to_string(n) +
                    " alpha=" + std::to_string(alpha),
                  n,
                  tol,
                  [&]() { call(ours, b.data()); },
                  [&]() { call(library, reference.data()); },
                  b,
                  reference);
              }
    // Side R is never narrowed.
    const int           n = 1, one = 1;
    const Real          al = 1;
    auto                b = values<Real>(ldb, 0.5), reference = b;
    const unsigned long before = formsolve::app::narrowed_blas_calls();
    for (auto [f, into] :
         {std::pair{ours, b.data()}, std::pair{library, reference.data()}})
      f("R", "U", "N", "N", &one, &n, &al, a.data(), &lda, into, &ldb);
    test::close(kind + " side R: passed on unchanged",
                formsolve::app::narrowed_blas_calls() == before &&
                  max_relative_difference(b, reference) == 0,
                1,
                0);
  }
} // namespace

int main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       lib_sgemm =
    reinterpret_cast<Gemm<float>>(library_function("sgemm_"));
  const auto lib_dgemm =
    reinterpret_cast<Gemm<double>>(library_function("dgemm_"));
  const auto lib_strsm =
    reinterpret_cast<Trsm<float>>(library_function("strsm_"));
  const auto lib_dtrsm =
    reinterpret_cast<Trsm<double>>(library_function("dtrsm_"));
  test::close("the BLAS library's own functions found",
              lib_sgemm && lib_dgemm && lib_strsm && lib_dtrsm,
              1,
              0);
  if (!(lib_sgemm && lib_dgemm && lib_strsm && lib_dtrsm))
    return test::result();
  test::close("these are not the core library's definitions",
              reinterpret_cast<void *>(lib_sgemm) !=
                reinterpret_cast<void *>(&sgemm_),
              1,
              0);
  check_gemm<float>(sgemm_, lib_sgemm, 1e-5);
  check_gemm<double>(dgemm_, lib_dgemm, 1e-13);
  check_trsm<float>(strsm_, lib_strsm, 1e-5);
  check_trsm<double>(dtrsm_, lib_dtrsm, 1e-13);

  {
    // Switched off: the library's function, bitwise.
    formsolve::app::set_narrow_blas(false);
    const int   m = 20, n = 1, k = 20;
    const float al = 1, be = 1;
    const auto  a = values<float>(m * k, 0.3), b = values<float>(k, 0.4);
    auto        c = values<float>(m, 0.5), reference = c;
    const unsigned long before = formsolve::app::narrowed_blas_calls();
    sgemm_("N",
           "N",
           &m,
           &n,
           &k,
           &al,
           a.data(),
           &m,
           b.data(),
           &k,
           &be,
           c.data(),
           &m);
    lib_sgemm("N",
              "N",
              &m,
              &n,
              &k,
              &al,
              a.data(),
              &m,
              b.data(),
              &k,
              &be,
              reference.data(),
              &m);
    test::close("switched off: the library's result, bitwise, not narrowed",
                formsolve::app::narrowed_blas_calls() == before &&
                  max_relative_difference(c, reference) == 0,
                1,
                0);
    formsolve::app::set_narrow_blas(true);
  }

  {
    // MUMPS's substitution reaches the narrowed functions; its solution is
    // that of the library's kernels to round-off.
    using namespace formsolve::solver;
    const IndexSet                 owned = test::owned_rows(4000);
    TrilinosWrappers::SparseMatrix A;
    test::build(A, owned);
    test::TVector b(owned, test::comm);
    for (const auto i : owned)
      b(i) = std::sin(0.01 * i);
    b.compress(VectorOperation::insert);
    MumpsDirect::Settings settings;
    MumpsDirect           direct(test::comm, settings);
    direct.analyse(A);
    direct.factorise(A);
    test::TVector       x(owned, test::comm), x_library(owned, test::comm);
    const unsigned long before = formsolve::app::narrowed_blas_calls();
    direct.solve(x, b);
    const unsigned long calls = formsolve::app::narrowed_blas_calls() - before;
    formsolve::app::set_narrow_blas(false);
    direct.solve(x_library, b);
    formsolve::app::set_narrow_blas(true);
    std::cout << "      MUMPS solve: " << calls << " narrowed calls"
              << std::endl;
    test::close("MUMPS's solve reaches the narrowed functions",
                calls > 0,
                1,
                0);
    x_library -= x;
    test::close("MUMPS's solution as with the library's kernels (relative)",
                x_library.l2_norm() / x.l2_norm(),
                0,
                1e-12);
  }
  return test::result();
}
