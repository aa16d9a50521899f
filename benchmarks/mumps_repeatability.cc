// Is MUMPS bitwise repeatable on this stack? (doc/reliability.md, section 5)
// One matrix, assembled once: a 3-D 7-point convection-diffusion operator on
// m^3 nodes (unsymmetric, rows split evenly over the ranks). Factorised and
// solved through formsolve's MumpsDirect six times, each solution compared bit
// for bit with the first:
// - "factorise": a fresh instance each time (analysis, factorisation, solve);
// - "solve": the factors of one instance, solved again.
// Prints the number of entries that differ and the largest difference.
//   mpirun -np N build/mumps_repeatability [m]
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/linear/mumps_direct.h>

#include <array>
#include <cmath>
#include <cstring>
#include <iostream>

using namespace dealii;
using formsolve::solver::MumpsDirect;
using TVector = TrilinosWrappers::MPI::Vector;

namespace
{
  const MPI_Comm comm = MPI_COMM_WORLD;

  /// The operator: diagonal 6.1 + sin(row), neighbours -1 plus a drift.
  void build(TrilinosWrappers::SparseMatrix &A, const IndexSet &owned, int m)
  {
    const std::array<std::array<int, 3>, 6> steps = {{{{1, 0, 0}},
                                                      {{-1, 0, 0}},
                                                      {{0, 1, 0}},
                                                      {{0, -1, 0}},
                                                      {{0, 0, 1}},
                                                      {{0, 0, -1}}}};
    auto neighbours = [&](const types::global_dof_index row, auto &&visit) {
      const int i = row % m, j = (row / m) % m, k = row / (m * m);
      for (const auto &s : steps)
        {
          const int a = i + s[0], b = j + s[1], c = k + s[2];
          if (a >= 0 && b >= 0 && c >= 0 && a < m && b < m && c < m)
            visit((c * m + b) * m + a, s);
        }
    };
    DynamicSparsityPattern dsp(owned.size(), owned.size(), owned);
    for (const auto row : owned)
      {
        dsp.add(row, row);
        neighbours(row,
                   [&](const int col, const auto &) { dsp.add(row, col); });
      }
    A.reinit(owned, owned, dsp, comm);
    for (const auto row : owned)
      {
        A.set(row, row, 6.1 + std::sin(row));
        neighbours(row, [&](const int col, const auto &s) {
          A.set(row,
                col,
                -1. + 0.2 * (s[0] + 0.5 * s[1]) + 0.01 * std::cos(row));
        });
      }
    A.compress(VectorOperation::insert);
  }

  /// Prints how many entries of @p x differ from @p x0 in any bit.
  void compare(const std::string &what,
               const unsigned int run,
               const TVector     &x,
               const TVector     &x0)
  {
    unsigned int differ  = 0;
    double       largest = 0;
    for (const auto i : x.locally_owned_elements())
      {
        const double a = x(i), b = x0(i);
        differ += std::memcmp(&a, &b, sizeof(double)) != 0;
        largest = std::max(largest, std::abs(a - b));
      }
    differ            = Utilities::MPI::sum(differ, comm);
    largest           = Utilities::MPI::max(largest, comm);
    const double size = x0.linfty_norm();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << what << ' ' << run << ": " << differ << " of " << x.size()
                << " entries differ, largest difference " << largest / size
                << " of max|x|" << std::endl;
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int                        m = argc > 1 ? std::atoi(argv[1]) : 30;
  const unsigned int               n = m * m * m;
  const unsigned int rank            = Utilities::MPI::this_mpi_process(comm),
                     size            = Utilities::MPI::n_mpi_processes(comm);
  IndexSet owned(n);
  owned.add_range(rank * n / size, (rank + 1) * n / size);
  TrilinosWrappers::SparseMatrix A;
  build(A, owned, m);
  TVector b(owned, comm), x0(owned, comm), x(owned, comm);
  for (const auto i : owned)
    b(i) = std::sin(0.01 * i) + 1;
  b.compress(VectorOperation::insert);

  const MumpsDirect::Settings settings;
  MumpsDirect                 first(comm, settings);
  first.analyse(A);
  first.factorise(A);
  first.solve(x0, b);
  for (unsigned int run = 1; run < 6; ++run)
    {
      MumpsDirect fresh(comm, settings);
      fresh.analyse(A);
      fresh.factorise(A);
      fresh.solve(x, b);
      compare("factorise", run, x, x0);
    }
  for (unsigned int run = 1; run < 6; ++run)
    {
      first.solve(x, b);
      compare("solve", run, x, x0);
    }
}
