// The mid-surface of a section (plane strain, axisymmetric) before and after
// the release, gathered on every rank: one node per column, from the node
// layer nearest the sheet's mid-plane. A section's profile is one line of
// nodes, small next to the mesh.
#pragma once

#include <formsolve/springback/channel_measures.h>
#include <formsolve/springback/release.h>

#include <vector>

namespace formsolve
{
  namespace springback
  {
    /// The profile of @p release on @p state's section (empty in 3-D).
    /// Collective.
    template <int dim>
    std::vector<ProfilePoint> section_profile(const Release<dim>      &release,
                                              const state::State<dim> &state);
  } // namespace springback
} // namespace formsolve
