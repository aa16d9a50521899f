// Two right-hand sides on one matrix (solver/mumps_solver_pair.cc): the
// body correction and the blank holder's column. On the penalty operator of
// penalty_operator.h:
// - MUMPS's solve of two columns at once gives what two solves give;
// - flexible_gmres_pair converges each solve as flexible_gmres alone does,
//   with both vectors preconditioned in one call while both run and the
//   longer one alone after that;
// - MumpsSolver::solve_pair with single-precision factors and reuse
//   factorises once, reuses the factors on slightly changed values, and
//   factorises once more when they fail on strongly changed ones; every
//   solution meets Reuse tolerance. With exact factors it is two solve()s.
// 1 and 2 ranks.
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/linear/flexible_gmres.h>
#include <formsolve/linear/mumps_direct.h>
#include <formsolve/linear/mumps_solver.h>
#include <formsolve/parameters/solvers.h>

#include "check.h"
#include "penalty_operator.h"

#include <cmath>

using namespace dealii;
using formsolve::solver::MumpsSolver;
using test::comm;
using test::true_residual;
using test::TVector;

namespace
{
  TVector right_hand_side(const IndexSet &owned, const double frequency)
  {
    TVector b(owned, comm);
    for (const auto i : owned)
      b(i) = std::sin(frequency * i) + (i % 37 == 0 ? 10. : 0.);
    b.compress(VectorOperation::insert);
    return b;
  }

  double relative_difference(const TVector &a, const TVector &b)
  {
    TVector d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  // Every diagonal entry scaled by (1 + change), the penalty rows by
  // penalty_factor more; the matrix object and its pattern stay.
  void change_values(TrilinosWrappers::SparseMatrix &A,
                     const double                    change,
                     const double                    penalty_factor)
  {
    for (const auto i : A.locally_owned_range_indices())
      {
        const double d = A.diag_element(i);
        A.set(i, i, d * (1 + change) * (i % 37 == 0 ? penalty_factor : 1.));
      }
    A.compress(VectorOperation::insert);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace formsolve::solver;
  const IndexSet                 owned = test::owned_rows(4000);
  TrilinosWrappers::SparseMatrix A;
  test::build(A, owned);
  const TVector b = right_hand_side(owned, 0.01);
  const TVector c = right_hand_side(owned, 0.037);

  {
    // Two columns in one MUMPS solve: the solutions of two solves.
    MumpsDirect::Settings exact;
    MumpsDirect           direct(comm, exact);
    direct.analyse(A);
    direct.factorise(A);
    TVector x0(owned, comm), x1(owned, comm), y0(owned, comm), y1(owned, comm);
    direct.solve(x0, b);
    direct.solve(x1, c);
    direct.solve(y0, b, y1, c);
    test::close("two columns at once: the first solution",
                relative_difference(y0, x0),
                0,
                1e-12);
    test::close("two columns at once: the second solution",
                relative_difference(y1, x1),
                0,
                1e-12);
  }

  {
    // Side by side with single-precision factors, to tolerances that need
    // different iteration counts.
    MumpsDirect::Settings single;
    single.single_precision = true;
    MumpsDirect factors(comm, single);
    factors.analyse(A);
    factors.factorise(A);
    const auto   vmult = [&A](TVector &d, const TVector &s) { A.vmult(d, s); };
    unsigned int single_calls = 0, pair_calls = 0;
    const auto   one = [&](TVector &d, const TVector &s) {
      ++single_calls;
      factors.solve(d, s);
    };
    const auto two =
      [&](TVector &d0, const TVector &s0, TVector &d1, const TVector &s1) {
        ++pair_calls;
        factors.solve(d0, s0, d1, s1);
      };
    const double tol_b = 1e-10 * b.l2_norm(), tol_c = 1e-4 * c.l2_norm();
    TVector      x(owned, comm), y(owned, comm);
    const auto   results =
      flexible_gmres_pair(vmult, one, two, x, b, tol_b, 50, y, c, tol_c, 50);
    std::cout << "      side by side: " << results[0].iterations << " and "
              << results[1].iterations << " iterations, " << pair_calls
              << " paired and " << single_calls << " single applications"
              << std::endl;
    test::close("side by side: both converged",
                results[0].converged && results[1].converged,
                1,
                0);
    test::close("side by side: the first true residual within its tolerance",
                true_residual(A, x, b) <= tol_b * (1 + 1e-6),
                1,
                0);
    test::close("side by side: the second true residual within its tolerance",
                true_residual(A, y, c) <= tol_c * (1 + 1e-6),
                1,
                0);
    test::close("side by side: the tighter solve needs more iterations",
                results[0].iterations > results[1].iterations,
                1,
                0);
    test::close("side by side: paired applications while both run",
                pair_calls,
                results[1].iterations,
                0);
    test::close("side by side: single applications for the longer one",
                single_calls,
                results[0].iterations - results[1].iterations,
                0);
    single_calls = 0;
    TVector    alone_x(owned, comm), alone_y(owned, comm);
    const auto alone_b = flexible_gmres(vmult, one, alone_x, b, tol_b, 50);
    const auto alone_c = flexible_gmres(vmult, one, alone_y, c, tol_c, 50);
    test::close("side by side: the iterations of the first solve alone",
                results[0].iterations,
                alone_b.iterations,
                1);
    test::close("side by side: the iterations of the second solve alone",
                results[1].iterations,
                alone_c.iterations,
                1);
  }

  {
    // Side by side with Jacobi (many iterations): each solve is exactly
    // the one it is alone, iterate for iterate.
    const IndexSet                 small = test::owned_rows(300);
    TrilinosWrappers::SparseMatrix C;
    test::build(C, small);
    for (const auto i : small)
      if (i % 37 == 0)
        C.set(i, i, 3.); // no penalty: a moderate condition number
    C.compress(VectorOperation::insert);
    const TVector d  = right_hand_side(small, 0.1),
                  e  = right_hand_side(small, 1.);
    const auto cmult = [&C](TVector &dst, const TVector &src) {
      C.vmult(dst, src);
    };
    const auto jacobi = [&C](TVector &dst, const TVector &src) {
      for (const auto i : dst.locally_owned_elements())
        dst(i) = src(i) / C.diag_element(i);
      dst.compress(VectorOperation::insert);
    };
    const auto jacobi_pair = [&jacobi](TVector       &d0,
                                       const TVector &s0,
                                       TVector       &d1,
                                       const TVector &s1) {
      jacobi(d0, s0);
      jacobi(d1, s1);
    };
    TVector    x(small, comm), y(small, comm), x1(small, comm), y1(small, comm);
    const auto both = flexible_gmres_pair(cmult,
                                          jacobi,
                                          jacobi_pair,
                                          x,
                                          d,
                                          1e-7 * d.l2_norm(),
                                          2000,
                                          y,
                                          e,
                                          1e-3 * e.l2_norm(),
                                          2000);
    const auto alone_d =
      flexible_gmres(cmult, jacobi, x1, d, 1e-7 * d.l2_norm(), 2000);
    const auto alone_e =
      flexible_gmres(cmult, jacobi, y1, e, 1e-3 * e.l2_norm(), 2000);
    std::cout << "      Jacobi side by side: " << both[0].iterations << " and "
              << both[1].iterations << " iterations" << std::endl;
    test::close("Jacobi side by side: both converged, the first later",
                both[0].converged && both[1].converged &&
                  both[0].iterations > both[1].iterations,
                1,
                0);
    test::close("Jacobi side by side: the first solve's iterations alone",
                both[0].iterations,
                alone_d.iterations,
                0);
    test::close("Jacobi side by side: the second solve's iterations alone",
                both[1].iterations,
                alone_e.iterations,
                0);
    test::close("Jacobi side by side: the first solution alone",
                relative_difference(x, x1),
                0,
                1e-14);
    test::close("Jacobi side by side: the second solution alone",
                relative_difference(y, y1),
                0,
                1e-14);
  }

  {
    // LinearSolver: the shipped 3-D case's factor settings.
    formsolve::parameters::LinearSolver prm;
    prm.factor_precision =
      formsolve::parameters::FactorPrecision::single_precision;
    prm.reuse_iterations = 10;
    prm.reuse_tolerance  = 1e-6;
    MumpsSolver solver(prm, false);
    TVector     x(owned, comm), y(owned, comm);
    const auto  within = [&](const std::string &what) {
      test::close(what + ": first solution within Reuse tolerance",
                  true_residual(A, x, b) <= 1e-6 * b.l2_norm() * 1.001,
                  1,
                  0);
      test::close(what + ": second solution within Reuse tolerance",
                  true_residual(A, y, c) <= 1e-6 * c.l2_norm() * 1.001,
                  1,
                  0);
    };
    solver.solve_pair(A, x, b, y, c);
    test::close("first pair: one factorisation", solver.factorisations(), 1, 0);
    within("first pair");
    change_values(A, 0.01, 1.);
    x                      = 0;
    y                      = 0;
    const unsigned int its = solver.solve_pair(A, x, b, y, c);
    std::cout << "      values changed by 1 %: " << its
              << " iterations for both" << std::endl;
    test::close("values changed by 1 %: the factors reused",
                solver.factorisations(),
                1,
                0);
    within("values changed by 1 %");
    change_values(A, 0., 1e3);
    x = 0;
    y = 0;
    solver.solve_pair(A, x, b, y, c);
    test::close("penalty rows 1000x stiffer: one more factorisation",
                solver.factorisations(),
                2,
                0);
    within("penalty rows 1000x stiffer");
  }

  {
    // Exact factors: the pair solves as two solves on the same matrix do.
    formsolve::parameters::LinearSolver prm;
    MumpsSolver                         pair(prm, false), apart(prm, false);
    TVector x(owned, comm), y(owned, comm), x1(owned, comm), y1(owned, comm);
    pair.solve_pair(A, x, b, y, c);
    apart.solve(A, x1, b);
    apart.solve(A, y1, c);
    test::close("exact: one factorisation for the pair",
                pair.factorisations(),
                1,
                0);
    test::close("exact: the first solution of two solves",
                relative_difference(x, x1),
                0,
                1e-12);
    test::close("exact: the second solution of two solves",
                relative_difference(y, y1),
                0,
                1e-12);
  }
  return test::result();
}
