// The Lanczos condition estimate (solver/condition_estimate.cc, Linear
// solver/Condition estimate iterations) on diag(1, ..., n): with n CG steps
// the tridiagonal holds every eigenvalue, so the estimate is n; with fewer it
// is a lower bound that grows with the steps. 1 and 2 ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <formsolve/linear/condition_estimate.h>

#include "check.h"
#include "penalty_operator.h"

#include <cmath>

using namespace dealii;

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n     = 60;
  const IndexSet                   owned = test::owned_rows(n);
  DynamicSparsityPattern           dsp(n, n, owned);
  for (const auto i : owned)
    dsp.add(i, i);
  TrilinosWrappers::SparseMatrix A;
  A.reinit(owned, owned, dsp, test::comm);
  test::TVector b(owned, test::comm);
  for (const auto i : owned)
    {
      A.set(i, i, 1. + i);
      b(i) = 1. + 0.5 * std::sin(3. * i); // every eigenvector present
    }
  A.compress(VectorOperation::insert);
  b.compress(VectorOperation::insert);

  const double full = formsolve::solver::estimate_condition(A, b, n);
  test::close("n steps: cond = n", full, n, 1e-6 * n);
  double previous = 0;
  for (const unsigned int steps : {3u, 8u, 20u})
    {
      const double c = formsolve::solver::estimate_condition(A, b, steps);
      test::close(std::to_string(steps) + " steps: a lower bound, growing",
                  c > previous && c <= n * (1 + 1e-12),
                  1,
                  0);
      previous = c;
    }
  return test::result();
}
