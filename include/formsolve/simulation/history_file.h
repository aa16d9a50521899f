// history.csv: one row per converged step, written on rank 0.
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace formsolve
{
  namespace simulation
  {
    class HistoryFile
    {
    public:
      /// Opens (truncates) @p path on rank 0 and writes the header.
      HistoryFile(const std::string              &path,
                  const std::vector<std::string> &columns,
                  const bool                      is_root);

      /// Appends one row; @p values in the order of the columns. Flushed, so a
      /// run that stops early keeps every finished step.
      void write_row(const std::vector<double> &values);

    private:
      std::ofstream out;
      std::size_t   n_columns;
    };
  } // namespace simulation
} // namespace formsolve
