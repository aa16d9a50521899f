// Where a sheet column's records meet: every planform key has one owning
// rank (a hash of the key), so that the records of a column's nodes and
// cells, on whatever ranks the partition put them, are summed there and the
// sheet measures need no rank to hold the whole sheet. Also the pick of one
// point among the ranks' candidates that every rank makes alike.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <formsolve/model/position_order.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    /// The rank that owns the column of planform key @p key.
    template <std::size_t n>
    unsigned int column_owner(const std::array<long long, n> &key,
                              const unsigned int              n_ranks)
    {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (const long long k : key)
        {
          // splitmix64's finaliser: neighbouring keys spread evenly.
          h ^= static_cast<std::uint64_t>(k) + 0x9e3779b97f4a7c15ull +
               (h << 6) + (h >> 2);
          h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
          h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
          h ^= h >> 31;
        }
      return static_cast<unsigned int>(h % n_ranks);
    }

    /// Records by destination rank, each a flat vector of doubles.
    using Outbox = std::map<unsigned int, std::vector<double>>;

    /// Sends @p out (collective); what each rank sent here, by rank.
    inline Outbox exchange_records(const MPI_Comm comm, const Outbox &out)
    {
      return dealii::Utilities::MPI::some_to_some(comm, out);
    }

    /// A point with the values it stands for, as a rank proposes it.
    template <int dim>
    struct Candidate
    {
      bool                valid = false;
      dealii::Point<dim>  point;
      std::vector<double> values;
    };

    /// Of the valid candidates of all ranks, the first in the canonical
    /// order of their points (collective; the same on every rank).
    template <int dim>
    Candidate<dim> first_in_order(const MPI_Comm        comm,
                                  const Candidate<dim> &mine)
    {
      std::vector<double> packed{mine.valid ? 1. : 0.};
      for (unsigned int d = 0; d < dim; ++d)
        packed.push_back(mine.point[d]);
      packed.insert(packed.end(), mine.values.begin(), mine.values.end());
      Candidate<dim> best;
      for (const auto &p : dealii::Utilities::MPI::all_gather(comm, packed))
        {
          Candidate<dim> c;
          c.valid = p[0] != 0.;
          for (unsigned int d = 0; d < dim; ++d)
            c.point[d] = p[1 + d];
          c.values.assign(p.begin() + 1 + dim, p.end());
          if (c.valid && (!best.valid || model::precedes(c.point, best.point)))
            best = c;
        }
      return best;
    }
  } // namespace postprocess
} // namespace formsolve
