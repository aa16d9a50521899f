// The parameter manual (doc/parameters.md), generated from the declarations
// so that it cannot drift from them: `formsolve --parameter-manual`.
#pragma once

#include <formsolve/parameters/declared.h>

#include <ostream>

namespace formsolve
{
  namespace parameters
  {
    /// Every subsection of @p declared as a Markdown table: entry, default,
    /// what it accepts, and its documentation (units included there).
    void write_manual(const DeclaredSection &declared, std::ostream &out);

    /// A complete parameter file with the defaults, each entry preceded by
    /// its documentation and what it accepts (`formsolve
    /// --print-parameters`).
    void write_parameter_file(const DeclaredSection &declared,
                              std::ostream          &out);
  } // namespace parameters
} // namespace formsolve
