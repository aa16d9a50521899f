// The sprung part on file: springback_<step>.pvtu on the sprung mesh (the
// current configuration plus the springback displacement), with the
// displacement itself and the residual and end-of-forming stresses.
#pragma once

#include <formsolve/springback/release.h>

#include <string>

namespace formsolve
{
  namespace springback
  {
    /// Writes the release's results into @p directory (collective); returns
    /// the record's name. The sprung mesh is the state's current one plus
    /// the release's displacement (solved on the configuration a step
    /// earlier: a difference of second order).
    template <int dim>
    std::string write_sprung_part(const Release<dim>      &release,
                                  const state::State<dim> &state,
                                  const std::string       &directory);

    /// The sprung part's displacement on the state's DoFs (owned): the
    /// forming's plus the release's, interpolated to the forming's element
    /// (the shape a next operation starts from).
    template <int dim>
    state::VectorType sprung_displacement(const Release<dim>      &release,
                                          const state::State<dim> &state);
  } // namespace springback
} // namespace formsolve
