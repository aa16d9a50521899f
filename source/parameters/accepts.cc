#include <formsolve/parameters/accepts.h>

#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;

    namespace
    {
      std::string shown(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }

      /// ">= 0", "from 0 to 1", "" for the whole line.
      std::string range(const double lower, const double upper)
      {
        const bool open_lower = lower <= -unbounded,
                   open_upper = upper >= unbounded;
        if (open_lower && open_upper)
          return "";
        if (open_upper)
          return " >= " + shown(lower);
        if (open_lower)
          return " <= " + shown(upper);
        return " from " + shown(lower) + " to " + shown(upper);
      }

      std::string in_unit(const std::string &unit)
      {
        return unit.empty()  ? ""
               : unit == "-" ? ", dimensionless"
                             : ", in " + unit;
      }

      /// "a|b" -> "`a`, `b`".
      std::string listed(const std::string &names)
      {
        std::string        out;
        std::istringstream in(names);
        for (std::string name; std::getline(in, name, '|');)
          out += (out.empty() ? "`" : ", `") + name + "`";
        return out;
      }
    } // namespace

    Accepts
    number(const std::string &unit, const double lower, const double upper)
    {
      Accepts a;
      a.pattern = std::make_shared<Double>(
        lower <= -unbounded ? Double::min_double_value : lower,
        upper >= unbounded ? Double::max_double_value : upper);
      a.words          = "a number" + range(lower, upper) + in_unit(unit);
      a.takes_decimals = true;
      return a;
    }

    Accepts numbers(const std::string &unit,
                    const unsigned int min_count,
                    const unsigned int max_count,
                    const double       lower)
    {
      Accepts      a;
      const Double each(lower <= -unbounded ? Double::min_double_value : lower);
      a.pattern =
        std::make_shared<List>(each,
                               min_count,
                               max_count == 0 ? List::max_int_value : max_count,
                               ",");
      const std::string count = max_count == 0 ? "numbers"
                                : min_count == max_count
                                  ? std::to_string(min_count) + " numbers"
                                  : std::to_string(min_count) + " to " +
                                      std::to_string(max_count) + " numbers";
      a.words =
        count + range(lower, unbounded) + ", comma-separated" + in_unit(unit);
      return a;
    }

    Accepts whole_number(const int lower, const int upper)
    {
      Accepts a;
      a.pattern = std::make_shared<Integer>(lower, upper);
      a.words =
        "a whole number" +
        range(lower,
              upper == std::numeric_limits<int>::max() ? unbounded : upper);
      return a;
    }

    Accepts true_or_false()
    {
      return {std::make_shared<Bool>(), "`true` or `false`"};
    }

    Accepts one_of(const std::string &names)
    {
      return {std::make_shared<Selection>(names), "one of " + listed(names)};
    }

    Accepts some_of(const std::string &names)
    {
      return {std::make_shared<MultipleSelection>(names),
              "a comma-separated list of " + listed(names)};
    }

    Accepts input_file()
    {
      Accepts a{std::make_shared<FileName>(FileName::input),
                "a file path (relative to the .prm file that names it)"};
      a.names_input_file = true;
      return a;
    }

    Accepts text(const std::string &words)
    {
      return {std::make_shared<Anything>(), words};
    }
  } // namespace parameters
} // namespace formsolve
