// Tools whose Gap is measured from the part (Tools/<tool>/Gap measured
// from = part): each is moved along z until its smallest distance to the
// part's surface nodes facing it is its Gap (doc/next-operation.md).
#pragma once

#include <formsolve/state/state.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace simulation
  {
    /// Places those tools of @p state (collective; before the first step);
    /// returns a line per tool placed, saying how far it moved. Throws
    /// naming the tool if no part of the sheet faces it or it cannot come
    /// within Gap of the part along z.
    template <int dim>
    std::vector<std::string> place_tools_against_part(state::State<dim> &state);
  } // namespace simulation
} // namespace formsolve
