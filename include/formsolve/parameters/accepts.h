// What an entry accepts, written once: the deal.II pattern that checks a
// value, and the same in words for the manual, --print-parameters and the
// message about a value it refuses ("a number from 0 to 1, dimensionless").
#pragma once

#include <deal.II/base/patterns.h>

#include <limits>
#include <memory>
#include <string>

namespace formsolve
{
  namespace parameters
  {
    struct Accepts
    {
      std::shared_ptr<const dealii::Patterns::PatternBase> pattern;
      std::string                                          words;
      /// A path taken from the .prm file that names it.
      bool names_input_file = false;
      /// A real number: a value with a decimal comma gets a hint.
      bool takes_decimals = false;
    };

    constexpr double unbounded = std::numeric_limits<double>::max();

    /// A real number in [@p lower, @p upper], in @p unit ("mm"; "-":
    /// dimensionless; "": said by the meaning).
    Accepts number(const std::string &unit,
                   const double       lower = -unbounded,
                   const double       upper = unbounded);
    /// Comma-separated real numbers >= @p lower, @p min_count to
    /// @p max_count of them (max_count 0: any number).
    Accepts numbers(const std::string &unit,
                    const unsigned int min_count,
                    const unsigned int max_count,
                    const double       lower = -unbounded);
    /// An integer in [@p lower, @p upper].
    Accepts whole_number(const int lower,
                         const int upper = std::numeric_limits<int>::max());
    Accepts true_or_false();
    /// One of the names "a|b|c".
    Accepts one_of(const std::string &names);
    /// A comma-separated selection of the names "a|b|c".
    Accepts some_of(const std::string &names);
    /// A path of an input file, relative to the .prm file that names it.
    Accepts input_file();
    /// Any text; @p words say which.
    Accepts text(const std::string &words);
  } // namespace parameters
} // namespace formsolve
