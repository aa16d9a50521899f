// The unsymmetric test operator of the linear-solver unit tests: -u'' + c u'
// on n nodes, every 37th row with a penalty 1e4 on its diagonal (a node in
// contact), cond ~ 1e7; rows split evenly over the ranks.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>

namespace test
{
  using TVector = dealii::TrilinosWrappers::MPI::Vector;

  inline const MPI_Comm comm = MPI_COMM_WORLD;

  inline dealii::IndexSet owned_rows(const unsigned int n)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm),
                       size = dealii::Utilities::MPI::n_mpi_processes(comm);
    dealii::IndexSet owned(n);
    owned.add_range(rank * n / size, (rank + 1) * n / size);
    return owned;
  }

  inline void build(dealii::TrilinosWrappers::SparseMatrix &A,
                    const dealii::IndexSet                 &owned)
  {
    const unsigned int             n = owned.size();
    dealii::DynamicSparsityPattern dsp(n, n, owned);
    for (const auto i : owned)
      for (unsigned int j = (i > 0 ? i - 1 : 0);
           j <= std::min<unsigned>(i + 1, n - 1);
           ++j)
        dsp.add(i, j);
    A.reinit(owned, owned, dsp, comm);
    for (const auto i : owned)
      {
        A.set(i, i, 2. + (i % 37 == 0 ? 1e4 : 0.));
        if (i > 0)
          A.set(i, i - 1, -1. - 0.3);
        if (i + 1 < n)
          A.set(i, i + 1, -1. + 0.3);
      }
    A.compress(dealii::VectorOperation::insert);
  }

  inline double true_residual(const dealii::TrilinosWrappers::SparseMatrix &A,
                              const TVector                                &x,
                              const TVector                                &b)
  {
    TVector r(b);
    A.vmult(r, x);
    r.sadd(-1., 1., b);
    return r.l2_norm();
  }
} // namespace test
