#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <formsolve/parameters/listed_names.h>

namespace formsolve
{
  namespace parameters
  {
    std::vector<std::string> listed_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides,
      const std::string                                      &path)
    {
      std::vector<std::string> parts;
      std::size_t              start = 0;
      for (std::size_t slash; (slash = path.find('/', start)) != path.npos;
           start = slash + 1)
        parts.push_back(path.substr(start, slash - start));
      const std::string        entry = path.substr(start);
      dealii::ParameterHandler prm;
      for (const auto &p : parts)
        prm.enter_subsection(p);
      prm.declare_entry(entry, "", dealii::Patterns::Anything());
      for (std::size_t i = 0; i < parts.size(); ++i)
        prm.leave_subsection();
      try
        {
          prm.parse_input_from_string(text, "", /*skip_undefined=*/true);
        }
      catch (const dealii::ExceptionBase &)
        {
          return {};
        }
      for (const auto &p : parts)
        prm.enter_subsection(p);
      std::string list = prm.get(entry);
      for (std::size_t i = 0; i < parts.size(); ++i)
        prm.leave_subsection();
      for (const auto &[where, value] : overrides)
        if (where == path)
          list = value;
      return dealii::Utilities::split_string_list(list);
    }
  } // namespace parameters
} // namespace formsolve
