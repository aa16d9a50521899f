#include <deal.II/base/exceptions.h>

#include <formsolve/simulation/history_file.h>

#include <iomanip>

namespace formsolve
{
  namespace simulation
  {
    HistoryFile::HistoryFile(const std::string              &path,
                             const std::vector<std::string> &columns,
                             const bool                      is_root)
        : n_columns(columns.size())
    {
      if (!is_root)
        return;
      out.open(path);
      AssertThrow(out.good(), dealii::ExcMessage("cannot write " + path));
      for (std::size_t i = 0; i < columns.size(); ++i)
        out << (i ? "," : "") << columns[i];
      out << '\n' << std::flush;
    }

    void HistoryFile::write_row(const std::vector<double> &values)
    {
      Assert(values.size() == n_columns, dealii::ExcInternalError());
      if (!out.is_open())
        return;
      out << std::setprecision(10);
      for (std::size_t i = 0; i < values.size(); ++i)
        out << (i ? "," : "") << values[i];
      out << '\n' << std::flush;
    }
  } // namespace simulation
} // namespace formsolve
