// Tables typed into one entry as "a:b, a:b, ...": the forming limit curve
// (minor:major strain), a force over the punch travel (travel:force).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    /// Whether @p text is one finite number (blanks around it allowed),
    /// then in @p x.
    bool read_number(const std::string &text, double &x);

    /// The pairs of @p text (empty items skipped); an item that is not two
    /// finite numbers around a colon throws naming @p entry and @p form
    /// ("minor:major").
    std::vector<std::pair<double, double>> read_pairs(const std::string &text,
                                                      const std::string &entry,
                                                      const std::string &form);

    /// The table @p points (first values increasing) at @p x: linear in
    /// between, the first and last values outside.
    double
    piecewise_linear(const std::vector<std::pair<double, double>> &points,
                     const double                                  x);
  } // namespace parameters
} // namespace formsolve
