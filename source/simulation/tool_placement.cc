#include <deal.II/base/exceptions.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/tool_placement.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;

    namespace
    {
      /// Tool @p t moved by @p s (mm) towards the sheet from @p start; its
      /// smallest distance to the facing surface nodes then (all ranks).
      template <int dim>
      double distance_at(state::State<dim>    &state,
                         const unsigned int    t,
                         const Tensor<1, dim> &start,
                         const double          s)
      {
        Tensor<1, dim> shift;
        shift[dim - 1] = -state.tools.side(t) * s;
        state.tools.restore(t, start + shift, 0., state.tools[t].velocity());
        return state.min_distance(t);
      }

      /// The largest move s towards the sheet at which tool @p t keeps at
      /// least @p gap from the part, by bracketing and bisection (the
      /// distance falls as the tool comes nearer).
      template <int dim>
      double placement(state::State<dim> &state,
                       const unsigned int t,
                       const double       gap)
      {
        const auto   start = state.tools[t].displacement();
        const double scale = state.prm.geometry.thickness;
        const auto   name  = "Tools/" + state.tools[t].name();
        auto         d     = [&](const double s) {
          return distance_at(state, t, start, s);
        };
        const double d0 = d(0);
        AssertThrow(d0 < std::numeric_limits<double>::max(),
                    ExcMessage(name + ": Gap measured from = part, but no "
                                      "part of the sheet's surface faces "
                                      "this tool"));
        // [lo, hi]: at lo the tool keeps Gap, at hi it does not.
        double       lo = 0, hi = 0, step = std::max(std::abs(d0 - gap), scale);
        unsigned int n = 0;
        if (d0 >= gap)
          for (hi = step; n < 60 && d(hi) >= gap; ++n)
            {
              lo = hi;
              step *= 2;
              hi = lo + step;
            }
        else
          for (lo = -step; n < 60 && d(lo) < gap; ++n)
            {
              hi = lo;
              step *= 2;
              lo = hi - step;
            }
        AssertThrow(n < 60,
                    ExcMessage(name + ": Gap measured from = part, but the "
                                      "tool never comes within Gap of the "
                                      "part along z (check its Shape and "
                                      "side of the sheet)"));
        while (hi - lo > 1e-9 * scale)
          {
            const double mid          = 0.5 * (lo + hi);
            (d(mid) >= gap ? lo : hi) = mid;
          }
        d(lo);
        return lo;
      }
    } // namespace

    template <int dim>
    std::vector<std::string> place_tools_against_part(state::State<dim> &state)
    {
      std::vector<std::string> said;
      state.update_contact_areas(); // which surface faces which tool
      for (unsigned int t = 0; t < state.tools.size(); ++t)
        {
          const double gap = state.tools.gap_to_part(t);
          if (std::isnan(gap))
            continue;
          const double       s = placement(state, t, gap);
          std::ostringstream line;
          line.precision(6);
          const double dz = -state.tools.side(t) * s; // along z
          line << "Tools/" << state.tools[t].name() << ": moved "
               << std::abs(dz) << " mm " << (dz < 0 ? "down" : "up")
               << " from where Gap puts it for a flat blank, to "
               << state.min_distance(t) << " mm from the part";
          said.push_back(line.str());
        }
      return said;
    }

#define INSTANTIATE(dim)                                           \
  template std::vector<std::string> place_tools_against_part<dim>( \
    state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
