// A canonical order of positions, so that the location reported for an
// extreme value that occurs at several symmetric points (the quarter cup is
// symmetric about its diagonal) does not depend on round-off, and so on the
// number of ranks: by angle about the z axis, then radius, then z.
#pragma once

#include <deal.II/base/point.h>

#include <array>
#include <cmath>

namespace formsolve
{
  namespace model
  {
    /// (angle about the z axis, radius, z) of @p x; in 2-D (r, z): (0, r, z).
    template <int dim>
    std::array<double, 3> canonical(const dealii::Point<dim> &x)
    {
      if constexpr (dim == 2)
        return {{0., x[0], x[1]}};
      else
        return {{std::atan2(x[1], x[0]), std::hypot(x[0], x[1]), x[2]}};
    }

    /// Whether @p a comes before @p b in the canonical order, components
    /// equal within 1e-9 (relative) counting as equal.
    template <int dim>
    bool precedes(const dealii::Point<dim> &a, const dealii::Point<dim> &b)
    {
      const auto p = canonical(a), q = canonical(b);
      for (unsigned int i = 0; i < 3; ++i)
        if (std::abs(p[i] - q[i]) > 1e-9 * (1 + std::abs(p[i])))
          return p[i] < q[i];
      return false;
    }

    /// Whether @p v is the extreme value @p extreme up to round-off.
    inline bool ties(const double v, const double extreme)
    {
      return std::abs(v - extreme) <= 1e-9 * std::abs(extreme) + 1e-300;
    }
  } // namespace model
} // namespace formsolve
