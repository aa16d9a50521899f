// A CSV table with one row per step (history.csv, refinement.csv), written
// on rank 0 and flushed per row. Values are set by column name; every
// declared column must be set before a row is written.
#pragma once

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    class StatisticsTable
    {
    public:
      /// Opens (truncates) @p path on rank 0 with @p columns as the header;
      /// with @p keep_rows >= 0 (a resumed run) the file keeps its header and
      /// that many rows, and the table continues after them.
      StatisticsTable(const std::string              &path,
                      const std::vector<std::string> &columns,
                      const bool                      is_root,
                      const int                       keep_rows = -1);

      /// Value of @p column in the current row.
      void set(const std::string &column, const double value);

      /// Writes the current row and starts a new one. Flushed, so a run
      /// that stops early keeps every finished row.
      void write_row();

      const std::vector<std::string> &columns() const { return names; }
      /// Rows in the file.
      unsigned int n_rows() const { return rows; }

    private:
      std::ofstream                      out;
      std::vector<std::string>           names;
      std::map<std::string, std::size_t> index;
      std::vector<double>                row;
      std::vector<bool>                  filled;
      unsigned int                       rows = 0;
    };
  } // namespace postprocess
} // namespace formsolve
