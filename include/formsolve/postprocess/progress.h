// The progress line of a run: an estimate of the time left from the rate at
// which recent steps approached the run's end, and wall times printed
// readably.
#pragma once

#include <deque>
#include <limits>
#include <string>
#include <utility>

namespace formsolve
{
  namespace postprocess
  {
    class Progress
    {
    public:
      /// @p window: how many recent steps the rate is taken over.
      explicit Progress(const unsigned int window = 20);

      /// Record the wall time (s) at punch travel @p travel (mm) and, for a
      /// run that ends by an event, how far it still is from it (@p to_go,
      /// mm: the flange left on the die, NaN if the run ends at a travel);
      /// the first call is the start.
      void
      record(const double wall,
             const double travel,
             const double to_go = std::numeric_limits<double>::quiet_NaN());

      /// The punch travel at which to_go reaches 0 at its recent rate per mm
      /// of travel, plus @p beyond (mm); infinite if not known yet.
      double end_travel(const double beyond) const;

      /// Wall time left to reach punch travel @p end at the recent rate
      /// (s), < 0 if not known yet.
      double time_left(const double end) const;

      /// "12.3 s", "2 min 05 s", "1 h 02 min".
      static std::string duration(const double seconds);

    private:
      unsigned int window;
      struct Point
      {
        double wall, travel, to_go;
      };
      std::deque<Point> points;
    };
  } // namespace postprocess
} // namespace formsolve
