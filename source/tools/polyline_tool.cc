#include <formsolve/tools/polyline_tool.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      /// Whether segments ab and cd cross (touching counts).
      bool segments_cross(const Point<2> &a,
                          const Point<2> &b,
                          const Point<2> &c,
                          const Point<2> &d)
      {
        const auto turn =
          [](const Point<2> &p, const Point<2> &q, const Point<2> &r) {
            const double x =
              (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
            return (x > 0) - (x < 0);
          };
        return turn(a, b, c) * turn(a, b, d) <= 0 &&
               turn(c, d, a) * turn(c, d, b) <= 0;
      }

      /// The unit normal on the right of a -> b.
      Tensor<1, 2> right_normal(const Point<2> &a, const Point<2> &b)
      {
        Tensor<1, 2> n;
        n[0] = b[1] - a[1];
        n[1] = a[0] - b[0];
        return n / n.norm();
      }
      using Chain = std::vector<std::array<unsigned int, 2>>;

      /// > 0 if the open @p chain must be reversed to face the sheet: the
      /// side the sheet's mid-plane (z = @p sheet_z) sees along z; each
      /// segment seen from it without another line in between votes with its
      /// horizontal extent. 0: the sheet sees nothing of it.
      double
      sheet_side_turn(const Chain                                    &chain,
                      const std::vector<Point<2>>                    &points,
                      const std::vector<std::array<unsigned int, 2>> &segments,
                      const double                                    sheet_z)
      {
        double turn = 0;
        for (const auto &s : chain)
          {
            const Point<2>     m = 0.5 * (points[s[0]] + points[s[1]]);
            const Tensor<1, 2> n = right_normal(points[s[0]], points[s[1]]);
            const double       to_plane = sheet_z - m[1];
            const double       length   = points[s[0]].distance(points[s[1]]);
            if (std::abs(to_plane) < 1e-9 * length || n[1] == 0)
              continue;
            const Point<2> a(m[0],
                             m[1] + 1e-9 * length * (to_plane > 0 ? 1 : -1)),
              b(m[0], sheet_z);
            bool hidden = false;
            for (const auto &o : segments)
              if ((o[0] != s[0] || o[1] != s[1]) &&
                  (o[0] != s[1] || o[1] != s[0]) &&
                  segments_cross(a, b, points[o[0]], points[o[1]]))
                hidden = true;
            if (!hidden)
              turn -= (to_plane > 0 ? 1 : -1) * n[1] * length;
          }
        return turn;
      }

      /// > 0 if the closed @p chain must be reversed to face outwards:
      /// counter-clockwise in (r, z) faces outwards on the right.
      double outward_turn(const Chain                 &chain,
                          const std::vector<Point<2>> &points)
      {
        double turn = 0;
        for (const auto &s : chain)
          turn += points[s[0]][0] * points[s[1]][1] -
                  points[s[1]][0] * points[s[0]][1];
        return -turn;
      }
    } // namespace

    PolylineTool::PolylineTool(const std::string  &name,
                               const ProfileLines &lines,
                               const std::string  &file,
                               const double        feature_angle,
                               const double        bend_radius,
                               const double        sheet_z,
                               const Tensor<1, 2> &velocity)
        : tool_name(name)
        , points(lines.points)
        , tool_velocity(velocity)
    {
      for (const auto &s : lines.segments)
        if (points[s[0]].distance(points[s[1]]) > 0)
          segments.push_back(s);
      AssertThrow(!segments.empty(),
                  ExcMessage(file + ": the profile has no segment of "
                                    "positive length"));
      orient(file, sheet_z);
      const unsigned int n = segments.size();
      normal.resize(n);
      for (unsigned int s = 0; s < n; ++s)
        normal[s] =
          right_normal(points[segments[s][0]], points[segments[s][1]]);
      // The segments at each point (head to tail after orient()).
      std::vector<int> into(points.size(), -1), out_of(points.size(), -1);
      for (unsigned int s = 0; s < n; ++s)
        {
          out_of[segments[s][0]] = s;
          into[segments[s][1]]   = s;
        }
      const double cos_feature = std::cos(feature_angle * M_PI / 180);
      corner_normal.resize(n);
      end_normal.resize(n);
      std::vector<bool> bent(n, false);
      for (unsigned int s = 0; s < n; ++s)
        for (unsigned int e = 0; e < 2; ++e)
          {
            const int other =
              e == 0 ? into[segments[s][0]] : out_of[segments[s][1]];
            corner_normal[s][e] = end_normal[s][e] = normal[s];
            if (other < 0)
              continue;
            const Tensor<1, 2> mean = normal[s] + normal[other];
            end_normal[s][e]        = mean / mean.norm();
            const double c          = normal[s] * normal[other];
            const double own        = points[segments[s][0]].distance(
                           points[segments[s][1]]),
                         next = points[segments[other][0]].distance(
                           points[segments[other][1]]);
            // A straight line given by its ends meets the short segments of
            // an arc at its tangent point: its normal is the vertex's there
            // (as a flat fan's in 3-D), or the line would bulge.
            if (c >= cos_feature)
              corner_normal[s][e] = own > 4 * next   ? normal[s]
                                    : next > 4 * own ? normal[other]
                                                     : end_normal[s][e];
            // Radius of the arc through the turn: length / angle.
            const double angle  = std::acos(std::min(1., c));
            const double length = 0.5 * (own + next);
            if (c < cos_feature || (angle > 0 && length / angle < bend_radius))
              bent[s] = true;
          }
      for (unsigned int s = 0; s < n; ++s)
        if (bent[s])
          bends.push_back(s);
      low = high = points[segments[0][0]];
      for (const auto &s : segments)
        for (const unsigned int v : s)
          for (unsigned int d = 0; d < 2; ++d)
            {
              low[d]  = std::min(low[d], points[v][d]);
              high[d] = std::max(high[d], points[v][d]);
            }
    }

    void PolylineTool::orient(const std::string &file, const double sheet_z)
    {
      std::vector<std::vector<unsigned int>> at(points.size());
      for (unsigned int s = 0; s < segments.size(); ++s)
        for (const unsigned int v : segments[s])
          at[v].push_back(s);
      for (unsigned int v = 0; v < points.size(); ++v)
        AssertThrow(at[v].size() <= 2,
                    ExcMessage(file + ": " + std::to_string(at[v].size()) +
                               " lines meet at the point r = " +
                               std::to_string(points[v][0]) +
                               ", z = " + std::to_string(points[v][1]) +
                               "; a profile is a chain of lines"));
      // Walk each chain from an end (open) or anywhere (closed), head to
      // tail.
      std::vector<bool>                        used(segments.size(), false);
      std::vector<std::array<unsigned int, 2>> ordered;
      std::vector<std::string>                 changes;
      for (const bool open : {true, false})
        for (unsigned int start = 0; start < points.size(); ++start)
          {
            if (at[start].empty() || (open && at[start].size() != 1))
              continue;
            Chain        chain;
            unsigned int v        = start;
            unsigned int as_given = 0;
            for (;;)
              {
                int next = -1;
                for (const unsigned int s : at[v])
                  if (!used[s])
                    next = s;
                if (next < 0)
                  break;
                used[next]           = true;
                const auto        &s = segments[next];
                const unsigned int w = s[0] == v ? s[1] : s[0];
                chain.push_back({{v, w}});
                as_given += s[0] == v;
                v = w;
              }
            if (chain.empty())
              continue;
            // > 0: the chain must be reversed.
            const double turn =
              open ? sheet_side_turn(chain, points, segments, sheet_z)
                   : outward_turn(chain, points);
            AssertThrow(!open || turn != 0,
                        ExcMessage(file + ": an open profile of which the "
                                          "sheet sees nothing along z, so its "
                                          "working side cannot be told; give "
                                          "the tool's closed section, or place "
                                          "it facing the sheet (Mesh offset)"));
            if (turn > 0)
              {
                std::reverse(chain.begin(), chain.end());
                for (auto &s : chain)
                  std::swap(s[0], s[1]);
                as_given = chain.size() - as_given;
              }
            // Said when the file's own direction of the lines is changed.
            if (as_given < chain.size())
              changes.push_back(
                std::to_string(chain.size() - as_given) + " of " +
                std::to_string(chain.size()) +
                (open ? " lines of an open chain turned to face the sheet"
                      : " lines of a closed chain turned to face outwards"));
            ordered.insert(ordered.end(), chain.begin(), chain.end());
          }
      segments = ordered;
      if (!changes.empty())
        note = file + ": " + changes.front() +
               (changes.size() > 1
                  ? " (and " + std::to_string(changes.size() - 1) + " more)"
                  : "");
    }

    PolylineTool::Closest PolylineTool::closest(const Point<2> &p) const
    {
      Closest best;
      best.distance = std::numeric_limits<double>::max();
      for (unsigned int s = 0; s < segments.size(); ++s)
        {
          const Point<2>    &a = points[segments[s][0]];
          const Tensor<1, 2> e = points[segments[s][1]] - a;
          const double       t = std::clamp(((p - a) * e) / (e * e), 0., 1.);
          const Point<2>     x = a + t * e;
          const double       d = p.distance(x);
          if (d < best.distance)
            best = {s, t, x, d};
        }
      return best;
    }

    double PolylineTool::signed_distance(const Point<2> &p_now,
                                         Tensor<1, 2>   &n) const
    {
      const Point<2>     p   = p_now - offset;
      const Closest      c   = closest(p);
      const unsigned int s   = c.segment;
      constexpr double   tol = 1e-10;
      const int          end = c.t < tol ? 0 : c.t > 1 - tol ? 1 : -1;
      // At a sharp corner or an open end the segments are the surface: the
      // sign from the mean normal there (a pseudo-normal, right on both
      // sides of a corner).
      if (end >= 0 && corner_normal[s][end] == normal[s])
        {
          const double sign = (p - c.point) * end_normal[s][end] < 0 ? -1 : 1;
          n = c.distance > tol ? sign * (p - c.point) / c.distance
                               : end_normal[s][end];
          return sign * c.distance;
        }
      // Phong's quadratic with shape factor 1/2 over the segment, as for
      // triangles (doc/theory.md eq. 7b).
      const double w[2]   = {1 - c.t, c.t};
      Point<2>     lifted = c.point;
      n                   = 0;
      for (unsigned int k = 0; k < 2; ++k)
        {
          const Tensor<1, 2> &nk = corner_normal[s][k];
          n += w[k] * nk;
          lifted += 0.5 * w[k] * ((points[segments[s][k]] - c.point) * nk) * nk;
        }
      n /= n.norm();
      return (p - lifted) * n;
    }

    double PolylineTool::signed_distance_within(const Point<2> &p,
                                                const double    reach,
                                                Tensor<1, 2>   &n) const
    {
      const Point<2> q = p - offset;
      for (unsigned int d = 0; d < 2; ++d)
        if (q[d] < low[d] - reach || q[d] > high[d] + reach)
          return 2 * reach;
      return signed_distance(p, n);
    }

    double PolylineTool::distance_to_radius(const Point<2> &p) const
    {
      double         d = std::numeric_limits<double>::infinity();
      const Point<2> q = p - offset;
      for (const unsigned int s : bends)
        {
          const Point<2>    &a = points[segments[s][0]];
          const Tensor<1, 2> e = points[segments[s][1]] - a;
          const double       t = std::clamp(((q - a) * e) / (e * e), 0., 1.);
          d                    = std::min(d, q.distance(a + t * e));
        }
      return d;
    }

    void PolylineTool::advance(const double dt)
    {
      offset += dt * tool_velocity;
      travelled += dt * tool_velocity.norm();
    }

    ToolSurface<2> PolylineTool::surface(const SurfaceExtent &) const
    {
      ToolSurface<2> s;
      for (const auto &x : points)
        s.points.push_back(x + offset);
      for (const auto &g : segments)
        s.cells.push_back(g);
      return s;
    }
  } // namespace tools
} // namespace formsolve
