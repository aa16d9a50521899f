// Entries that name subsections to come (Tools/Additional tools, Tools/Draw
// beads/Names): read from the input before it is parsed, so that the
// subsections they name can be declared first.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    /// The comma-separated names of the entry at @p path ("Tools/Additional
    /// tools") in the input @p text, or of its --set value in @p overrides;
    /// empty if the text does not parse (the real parse says why).
    std::vector<std::string> listed_names(
      const std::string                                      &text,
      const std::vector<std::pair<std::string, std::string>> &overrides,
      const std::string                                      &path);
  } // namespace parameters
} // namespace formsolve
