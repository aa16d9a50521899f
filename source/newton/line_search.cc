#include <formsolve/newton/line_search.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace solver
  {
    MeritHistory::MeritHistory(const unsigned int memory, const double first)
        : memory(memory)
        , merits{first}
    {}

    void MeritHistory::push(const double merit)
    {
      merits.push_back(merit);
      if (merits.size() > memory)
        merits.pop_front();
    }

    void MeritHistory::reset(const double merit)
    {
      merits.assign(1, merit);
    }

    double MeritHistory::reference() const
    {
      return *std::max_element(merits.begin(), merits.end());
    }

    LineSearch::LineSearch(const unsigned int max_steps)
        : max_steps(max_steps)
    {}

    LineSearchResult LineSearch::search(
      const double                                                g0,
      const double                                                m_ref,
      const std::function<LineSearchTrial(double, unsigned int)> &trial) const
    {
      LineSearchResult out;
      double           a_lo = 0, a_hi = 1, g_hi = 0;
      for (unsigned int ls = 0;; ++ls)
        {
          const LineSearchTrial t        = trial(out.alpha, ls);
          const bool            descends = t.merit < m_ref && t.slope < 0;
          if (!(g0 < 0) ||
              (t.merit < m_ref && std::abs(t.slope) <= 0.5 * std::abs(g0)) ||
              (descends && out.alpha == 1))
            return out;
          if (descends)
            a_lo = out.alpha;
          else
            {
              a_hi = out.alpha;
              g_hi = t.slope;
            }
          if (ls >= max_steps)
            {
              out.stalled = a_lo == 0;
              if (!out.stalled && out.alpha != a_lo)
                {
                  out.alpha     = a_lo;
                  out.evaluated = false;
                }
              return out;
            }
          if (a_lo > 0)
            out.alpha = 0.5 * (a_lo + a_hi);
          else if (g_hi > 0 && std::abs(g_hi) > 0.5 * std::abs(g0))
            out.alpha =
              std::clamp(a_hi * g0 / (g0 - g_hi), 0.1 * a_hi, 0.9 * a_hi);
          else
            out.alpha = 0.5 * a_hi;
        }
    }
  } // namespace solver
} // namespace formsolve
