// Helpers for parameter checks: user errors name the entry as
// "Subsection/Entry".
#pragma once

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <sstream>
#include <string>

namespace formsolve
{
  namespace parameters
  {
    inline void require(const bool         condition,
                        const std::string &entry,
                        const std::string &what)
    {
      AssertThrow(condition,
                  dealii::ExcMessage("Parameter " + entry + ": " + what));
    }

    inline std::string str(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// Finite and > 0 (NaN and inf fail).
    inline void require_positive(const double       x,
                                 const std::string &entry,
                                 const std::string &unit)
    {
      require(std::isfinite(x) && x > 0,
              entry,
              "must be positive" + (unit.empty() ? "" : " (" + unit + ")") +
                ", got " + str(x));
    }
  } // namespace parameters
} // namespace formsolve
