// What a ParameterHandler declares, as a plain tree (subsections, entries
// with their default, accepted values and documentation): read by the
// parameter manual and by the input check, which speak of entries in the
// user's words.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>

namespace formsolve
{
  namespace parameters
  {
    struct DeclaredEntry
    {
      std::string default_value;
      std::string
        pattern; // deal.II's description, e.g. "[Double 0...1 (inclusive)]"
      std::string documentation;
    };

    struct DeclaredSection
    {
      std::map<std::string, DeclaredSection> sections;
      std::map<std::string, DeclaredEntry>   entries;
    };

    /// A name as ParameterHandler's tree writes it (every character but
    /// [a-zA-Z0-9] as _xx, hexadecimal), back in the user's words.
    std::string demangle_name(const std::string &s);

    /// The declarations of @p prm.
    DeclaredSection declared(const dealii::ParameterHandler &prm);

    /// What a pattern accepts in plain words: "real >= 0", "integer in [1,
    /// 2]", "one of `a`, `b`", "`true` or `false`".
    std::string accepted_values(const std::string &pattern);
  } // namespace parameters
} // namespace formsolve
