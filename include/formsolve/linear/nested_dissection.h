// A fill-reducing ordering for sparse direct solvers: METIS nested
// dissection on the graph of a matrix. Debian's MUMPS is built without METIS,
// but accepts a given pivot order.
#pragma once

#include <mpi.h>

#include <vector>

namespace formsolve
{
  namespace solver
  {
    /// Pivot order of a structurally symmetric matrix of order @p n given by
    /// its nonzero positions (@p rows[k], @p cols[k]), 0-based; each
    /// off-diagonal position may appear once or twice (both triangles) and
    /// the diagonal is ignored. Returns position[i] = place of variable i in
    /// the elimination order (0-based), from METIS_NodeND. The DoFs of one
    /// node have identical closed neighbourhoods, which METIS compresses into
    /// one graph vertex.
    std::vector<int> nested_dissection(const int               n,
                                       const std::vector<int> &rows,
                                       const std::vector<int> &cols);

    /// The same for a matrix whose nonzero positions are spread over the
    /// ranks of @p comm (@p rows, @p cols 1-based, as MUMPS takes them): the
    /// pattern is gathered on rank 0, which runs METIS. Returns the 1-based
    /// positions on rank 0 (MUMPS's PERM_IN), nothing elsewhere. A failure
    /// throws on every rank.
    std::vector<int> gathered_nested_dissection(const MPI_Comm          comm,
                                                const int               n,
                                                const std::vector<int> &rows,
                                                const std::vector<int> &cols);
  } // namespace solver
} // namespace formsolve
