// A run's complete parameter listing (ParameterHandler::PRM), as a
// checkpoint keeps it: what a resumed run and a next operation compare
// with their own.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace simulation
  {
    /// The listing without the Output subsection and without comments: a
    /// run may be resumed with other output settings.
    std::string without_output(const std::string &listing);

    /// "Sub/Sub/Entry" -> value of a listing, the Output subsection left
    /// out.
    std::map<std::string, std::string> entries(const std::string &listing);

    /// The entries whose values differ between @p saved (the earlier run's,
    /// called @p earlier in the text) and @p now, with both values (at most
    /// ten); only entries whose key starts with one of @p prefixes (all if
    /// empty), except the keys in @p except.
    std::string differences(const std::string              &saved,
                            const std::string              &now,
                            const std::string              &earlier,
                            const std::vector<std::string> &prefixes = {},
                            const std::vector<std::string> &except   = {});
  } // namespace simulation
} // namespace formsolve
