#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <formsolve/linear/nested_dissection.h>

#include <metis.h>

#include <algorithm>
#include <string>

namespace formsolve
{
  namespace solver
  {
    std::vector<int> nested_dissection(const int               n,
                                       const std::vector<int> &rows,
                                       const std::vector<int> &cols)
    {
      static_assert(sizeof(idx_t) == sizeof(int), "METIS with 32-bit idx_t");
      // Adjacency in CSR form, both directions, no self loops, no repeats.
      std::vector<idx_t> degree(n + 1, 0);
      for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k] != cols[k])
          {
            ++degree[rows[k] + 1];
            ++degree[cols[k] + 1];
          }
      std::vector<idx_t> xadj(n + 1, 0);
      for (int i = 0; i < n; ++i)
        xadj[i + 1] = xadj[i] + degree[i + 1];
      std::vector<idx_t> adjncy(xadj[n]);
      std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1);
      for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k] != cols[k])
          {
            adjncy[fill[rows[k]]++] = cols[k];
            adjncy[fill[cols[k]]++] = rows[k];
          }
      // Both triangles given: each edge appears twice; METIS wants it once.
      idx_t end = 0;
      for (int i = 0; i < n; ++i)
        {
          const idx_t begin = end;
          std::sort(adjncy.begin() + xadj[i], adjncy.begin() + xadj[i + 1]);
          const auto last =
            std::unique(adjncy.begin() + xadj[i], adjncy.begin() + xadj[i + 1]);
          end =
            std::copy(adjncy.begin() + xadj[i], last, adjncy.begin() + end) -
            adjncy.begin();
          xadj[i] = begin;
        }
      xadj[n] = end;

      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      options[METIS_OPTION_NUMBERING] = 0;
      options[METIS_OPTION_COMPRESS]  = 1;
      idx_t              nv           = n;
      std::vector<idx_t> perm(n), position(n);
      const int          status = METIS_NodeND(&nv,
                                      xadj.data(),
                                      adjncy.data(),
                                      nullptr,
                                      options,
                                      perm.data(),
                                      position.data());
      AssertThrow(status == METIS_OK,
                  dealii::ExcMessage("METIS_NodeND failed (status " +
                                     std::to_string(status) + ")"));
      return std::vector<int>(position.begin(), position.end());
    }
    std::vector<int> gathered_nested_dissection(const MPI_Comm          comm,
                                                const int               n,
                                                const std::vector<int> &irn,
                                                const std::vector<int> &jcn)
    {
      using namespace dealii;
      const int  n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const bool root    = Utilities::MPI::this_mpi_process(comm) == 0;
      // The pattern on the root (MUMPS gathers it there too, for its
      // sequential analysis); METIS on its graph.
      const int        n_entries = irn.size();
      std::vector<int> entry_counts(n_ranks), entry_offsets(n_ranks + 1);
      MPI_Gather(&n_entries,
                 1,
                 MPI_INT,
                 entry_counts.data(),
                 1,
                 MPI_INT,
                 0,
                 comm);
      for (int p = 0; p < n_ranks; ++p)
        entry_offsets[p + 1] = entry_offsets[p] + entry_counts[p];
      std::vector<int> rows(root ? entry_offsets[n_ranks] : 0),
        columns(rows.size());
      std::vector<int> local(irn.size());
      for (unsigned int which = 0; which < 2; ++which)
        {
          const auto &source = which == 0 ? irn : jcn;
          auto       &target = which == 0 ? rows : columns;
          for (std::size_t k = 0; k < source.size(); ++k)
            local[k] = source[k] - 1;
          MPI_Gatherv(local.data(),
                      n_entries,
                      MPI_INT,
                      target.data(),
                      entry_counts.data(),
                      entry_offsets.data(),
                      MPI_INT,
                      0,
                      comm);
        }
      // METIS runs on the root only: its failure must stop every rank (the
      // others would wait in MUMPS's analysis).
      std::vector<int> position;
      std::string      failure;
      if (root)
        try
          {
            position = nested_dissection(n, rows, columns);
            for (auto &p : position)
              ++p;
          }
        catch (const std::exception &e)
          {
            failure = e.what();
          }
      failure = Utilities::MPI::broadcast(comm, failure, 0);
      AssertThrow(failure.empty(),
                  ExcMessage("Linear solver/Ordering = METIS: " + failure));
      return position;
    }
  } // namespace solver
} // namespace formsolve
