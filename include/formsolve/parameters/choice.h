// A selection entry written once: its names and the values they stand for in
// one list, from which come both the pattern of the declaration and the
// value the parse returns. A name added to the list is offered and parsed.
#pragma once

#include <deal.II/base/exceptions.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    template <typename T>
    class Choice
    {
    public:
      Choice(std::initializer_list<std::pair<const char *, T>> options)
          : options(options)
      {}

      /// "a|b|c", the argument of Patterns::Selection.
      std::string pattern() const
      {
        std::string p;
        for (const auto &[name, value] : options)
          p += (p.empty() ? "" : "|") + std::string(name);
        return p;
      }

      /// The value of @p name; ParameterHandler has already checked it
      /// against pattern().
      T parse(const std::string &name) const
      {
        for (const auto &[n, value] : options)
          if (name == n)
            return value;
        Assert(false,
               dealii::ExcMessage("'" + name + "' is not one of " + pattern()));
        return options.front().second;
      }

      /// The name of @p value (for messages and the written parameters).
      std::string name(const T value) const
      {
        for (const auto &[n, v] : options)
          if (v == value)
            return n;
        Assert(false, dealii::ExcInternalError());
        return "";
      }

    private:
      std::vector<std::pair<const char *, T>> options;
    };
  } // namespace parameters
} // namespace formsolve
