// The progress line of a run: an estimate of the time left from recent
// steps, and wall times printed readably.
#pragma once

#include <deque>
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
      explicit Progress(const unsigned int window = 8);

      /// Record the wall time (s) at punch travel @p travel (mm); the first
      /// call is the start.
      void record(const double wall, const double travel);

      /// Wall time left to reach @p stroke at the recent rate (s), < 0 if
      /// not known yet.
      double time_left(const double stroke) const;

      /// "12.3 s", "2 min 05 s", "1 h 02 min".
      static std::string duration(const double seconds);

    private:
      unsigned int                          window;
      std::deque<std::pair<double, double>> points; // (wall, travel)
    };
  } // namespace postprocess
} // namespace formsolve
