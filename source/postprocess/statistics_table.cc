#include <deal.II/base/exceptions.h>

#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/statistics_table.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace formsolve
{
  namespace postprocess
  {
    StatisticsTable::StatisticsTable(const std::string              &path,
                                     const std::vector<std::string> &columns,
                                     const bool                      is_root,
                                     const int                       keep_rows)
        : names(columns)
        , row(columns.size(), 0.)
        , filled(columns.size(), false)
    {
      for (std::size_t i = 0; i < names.size(); ++i)
        {
          Assert(index.count(names[i]) == 0, dealii::ExcInternalError());
          index[names[i]] = i;
        }
      rows = std::max(keep_rows, 0);
      if (!is_root)
        return;
      std::vector<std::string> kept;
      if (keep_rows >= 0)
        {
          std::ifstream old(path);
          std::string   line;
          std::getline(old, line); // the header
          while (kept.size() < unsigned(keep_rows) && std::getline(old, line))
            kept.push_back(line);
          AssertThrow(kept.size() == unsigned(keep_rows),
                      dealii::ExcMessage("--resume: " + path +
                                         " has fewer rows (" +
                                         std::to_string(kept.size()) +
                                         ") than the checkpoint (" +
                                         std::to_string(keep_rows) + ")"));
        }
      // The header and the kept rows replace the file in one step; the table
      // appends from there.
      write_atomically(path, [&](std::ostream &f) {
        for (std::size_t i = 0; i < names.size(); ++i)
          f << (i ? "," : "") << names[i];
        f << '\n';
        for (const auto &line : kept)
          f << line << '\n';
      });
      out.open(path, std::ios::app);
      AssertThrow(out.good(), dealii::ExcMessage("cannot write " + path));
    }

    void StatisticsTable::set(const std::string &column, const double value)
    {
      const auto it = index.find(column);
      AssertThrow(it != index.end(),
                  dealii::ExcMessage("statistics: no column named " + column));
      row[it->second]    = value;
      filled[it->second] = true;
    }

    void StatisticsTable::write_row()
    {
      for (std::size_t i = 0; i < names.size(); ++i)
        AssertThrow(filled[i],
                    dealii::ExcMessage("statistics: column " + names[i] +
                                       " was not set"));
      if (out.is_open())
        {
          // The row goes out in one write: a killed process leaves whole
          // rows.
          std::ostringstream line;
          line << std::setprecision(10);
          for (std::size_t i = 0; i < row.size(); ++i)
            line << (i ? "," : "") << row[i];
          line << '\n';
          out << line.str() << std::flush;
        }
      std::fill(filled.begin(), filled.end(), false);
      ++rows;
    }
  } // namespace postprocess
} // namespace formsolve
