#include <deal.II/base/exceptions.h>

#include <formsolve/solver/nested_dissection.h>

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
  } // namespace solver
} // namespace formsolve
