// A set force that may follow the punch travel: one number, constant over
// the stroke, or a table "travel:force, ..." (punch travel in mm, force in
// N), linear in between and held at the end values beyond, as a press's
// cushion curve is given (Tools/Blank holder/Force, Tools/<tool>/Force).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    struct ForceCurve
    {
      /// (punch travel mm, force N), travels increasing; one point: the
      /// force at every travel.
      std::vector<std::pair<double, double>> points = {{0., 0.}};

      static ForceCurve constant(const double force)
      {
        return ForceCurve{{{0., force}}};
      }
      /// A number or a table; throws naming @p entry where @p text is
      /// neither, or the travels do not increase.
      static ForceCurve read(const std::string &text, const std::string &entry);

      double at(const double travel) const;
      bool   varies() const { return points.size() > 1; }
      double smallest() const;
      double largest() const;
      /// As typed: "2300" or "0:1000, 20:3000".
      std::string text() const;
    };
  } // namespace parameters
} // namespace formsolve
