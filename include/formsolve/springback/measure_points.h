// The springback at points the user lists (Springback/Measure points): the
// displacement of the release at the mesh node nearest to each point of the
// formed part, and its component along the sheet's normal there (the
// mapped thickness direction of the blank).
#pragma once

#include <formsolve/springback/release.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace springback
  {
    struct PointSpringback
    {
      std::array<double, 3> node{};           // end of forming (mm)
      std::array<double, 3> normal{};         // unit, 3x3 frame
      std::array<double, 3> displacement{};   // mm, 3x3 frame
      double                along_normal = 0; // mm
    };

    /// At each of @p points (the model's coordinates). Collective; every
    /// rank gets all.
    template <int dim>
    std::vector<PointSpringback>
    springback_at(const Release<dim>                     &release,
                  const state::State<dim>                &state,
                  const std::vector<std::vector<double>> &points);
  } // namespace springback
} // namespace formsolve
