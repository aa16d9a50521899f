// The springback measures of a U-channel section (NUMISHEET'93 draw
// bending): the angle between the bottom and the wall (theta1), between the
// wall and the flange (theta2), and the wall's curl radius (rho), from the
// mid-surface of the section before and after the release. The bottom, wall
// and flange are the points that lay, at the end of forming, on the punch's
// flat face, between the two radii, and on the die's flat face beyond its
// radius (doc/springback.md).
#pragma once

#include <array>
#include <vector>

namespace formsolve
{
  namespace springback
  {
    /// One mid-surface node of the section: where it started (x), where it
    /// is at the end of forming and after the release (x, z).
    struct ProfilePoint
    {
      double                X0 = 0;
      std::array<double, 2> end{}, sprung{};
    };

    /// The tools that shaped the section: the punch's half-width and
    /// radius, the die opening's half-width and radius (mm).
    struct ChannelTools
    {
      double punch_half_width = 0, punch_radius = 0;
      double die_half_width = 0, die_radius = 0;
    };

    struct ChannelMeasures
    {
      /// Degrees (90 for a square U); mm (infinite: a straight wall). NaN
      /// where a segment has fewer than 3 points.
      double       theta1 = 0, theta2 = 0, rho = 0;
      unsigned int bottom = 0, wall = 0, flange = 0; // points of each
    };

    /// The measures of @p points (any order) at the end of forming
    /// (@p sprung false) or after the release.
    ChannelMeasures channel_measures(const std::vector<ProfilePoint> &points,
                                     const ChannelTools              &tools,
                                     const bool                       sprung);
  } // namespace springback
} // namespace formsolve
