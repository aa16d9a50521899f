#include <deal.II/base/exceptions.h>

#include <formsolve/postprocess/statistics_table.h>

#include <iomanip>

namespace formsolve
{
  namespace postprocess
  {
    StatisticsTable::StatisticsTable(const std::string              &path,
                                     const std::vector<std::string> &columns,
                                     const bool                      is_root)
        : names(columns)
        , row(columns.size(), 0.)
        , filled(columns.size(), false)
    {
      for (std::size_t i = 0; i < names.size(); ++i)
        {
          Assert(index.count(names[i]) == 0, dealii::ExcInternalError());
          index[names[i]] = i;
        }
      if (!is_root)
        return;
      out.open(path);
      AssertThrow(out.good(), dealii::ExcMessage("cannot write " + path));
      for (std::size_t i = 0; i < names.size(); ++i)
        out << (i ? "," : "") << names[i];
      out << '\n' << std::flush;
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
          out << std::setprecision(10);
          for (std::size_t i = 0; i < row.size(); ++i)
            out << (i ? "," : "") << row[i];
          out << '\n' << std::flush;
        }
      std::fill(filled.begin(), filled.end(), false);
    }
  } // namespace postprocess
} // namespace formsolve
