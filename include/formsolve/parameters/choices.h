// The names a choice entry offers, registered by the things they name: each
// penalty strategy registers its name for Contact/Penalty strategy from its
// own file. The parameters layer, the lowest, so declares the entry without
// including what it names, and a new strategy adds its name in one place.
#pragma once

#include <string>

namespace formsolve
{
  namespace parameters
  {
    /// Adds @p name to the choices of @p entry ("Subsection/Entry").
    /// Returns true, for registration by a static variable.
    bool add_choice(const std::string &entry, const std::string &name);

    /// The names registered for @p entry as "a|b|c" (sorted), the pattern
    /// of Patterns::Selection.
    std::string choices(const std::string &entry);
  } // namespace parameters
} // namespace formsolve
