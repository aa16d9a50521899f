// The surface of a ProfileTool for output: its (rho, z) profile (face,
// rounded edge, wall) swept along offsets of the planform's outline.
#include <formsolve/model/dimensions.h>
#include <formsolve/tools/profile_tool.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      constexpr unsigned int n_side = 8, n_corner = 8, n_arc = 12;

      /// The outline offset by rho (outward positive) in the first quadrant,
      /// from the +x to the +y axis, with a fixed number of points.
      template <int dim>
      std::vector<Point<2>> quadrant_outline(const Planform<dim> &p,
                                             const double         rho)
      {
        std::vector<Point<2>> q;
        if (p.kind != Planform<dim>::Kind::rounded_rectangle)
          {
            // A circle (the unbounded plane: a disk out to reach).
            const double r =
              std::max(0.,
                       p.kind == Planform<dim>::Kind::circle ? p.radius + rho
                                                             : rho);
            const unsigned int n = 2 * n_side + n_corner;
            for (unsigned int i = 0; i <= n; ++i)
              {
                const double phi = 0.5 * M_PI * i / n;
                q.emplace_back(r * std::cos(phi), r * std::sin(phi));
              }
            return q;
          }
        // The offset of a rounded rectangle: straight sides moved by rho,
        // corners of radius c + rho, or sharp where rho < -c.
        const double c = p.corner_radius, rc = std::max(c + rho, 0.);
        const double cx = std::max(p.half_length + rho - rc, 0.);
        const double cy = std::max(p.half_width + rho - rc, 0.);
        const double x = cx + rc, y = cy + rc;
        for (unsigned int i = 0; i < n_side; ++i)
          q.emplace_back(x, cy * i / n_side);
        for (unsigned int i = 0; i <= n_corner; ++i)
          {
            const double phi = 0.5 * M_PI * i / n_corner;
            q.emplace_back(cx + rc * std::cos(phi), cy + rc * std::sin(phi));
          }
        for (unsigned int i = n_side; i-- > 0;)
          q.emplace_back(cx * i / n_side, y);
        return q;
      }

      /// The quadrant outline repeated by the symmetry of the planform over
      /// the angles of the model, in the order of the angle.
      std::vector<Point<2>> ring(const std::vector<Point<2>> &q,
                                 const SurfaceExtent         &e)
      {
        std::vector<Point<2>> all;
        const int first = static_cast<int>(std::lround(e.first_angle / 90.));
        const int last  = static_cast<int>(std::lround(e.last_angle / 90.));
        for (int k = first; k < last; ++k)
          {
            const int quadrant = ((k % 4) + 4) % 4;
            // Quadrants 1 and 3 run against the outline: mirror and reverse.
            const bool mirrored = quadrant % 2 == 1;
            const int  sx       = quadrant == 1 || quadrant == 2 ? -1 : 1;
            const int  sy       = quadrant >= 2 ? -1 : 1;
            for (std::size_t i = 0; i < q.size(); ++i)
              {
                if (i == 0 && !all.empty())
                  continue; // shared with the previous quadrant
                const Point<2> &p = mirrored ? q[q.size() - 1 - i] : q[i];
                all.emplace_back(sx * p[0], sy * p[1]);
              }
          }
        if (last - first >= 4)
          all.pop_back(); // the full turn: the first point again
        return all;
      }

      /// (a, b) of the rounded quadrant {a >= 0, b >= 0} from the far end of
      /// the face over the edge of radius R to the end of the wall.
      std::vector<std::pair<double, double>>
      profile(const double a_max, const double R, const double b_max)
      {
        std::vector<std::pair<double, double>> ab;
        for (unsigned int i = 0; i < n_side; ++i)
          ab.emplace_back(a_max + (R - a_max) * i / n_side, 0.);
        for (unsigned int i = 0; i <= n_arc; ++i)
          {
            const double psi = 0.5 * M_PI * i / n_arc;
            ab.emplace_back(R - R * std::sin(psi), R - R * std::cos(psi));
          }
        for (unsigned int i = 1; i <= n_side; ++i)
          ab.emplace_back(0., R + (b_max - R) * i / n_side);
        return ab;
      }
    } // namespace

    template <int dim>
    ToolSurface<dim>
    ProfileTool<dim>::surface(const SurfaceExtent &extent) const
    {
      using Kind           = typename Planform<dim>::Kind;
      const bool unbounded = planform.kind == Kind::unbounded;
      Assert(dim == 3 || planform.kind != Kind::rounded_rectangle,
             ExcInternalError());
      const double outline =
        planform.kind == Kind::circle
          ? planform.radius
          : std::max(planform.half_length, planform.half_width);
      const double inradius =
        planform.kind == Kind::circle
          ? planform.radius
          : std::min(planform.half_length, planform.half_width);
      const double R = profile_radius;
      // The punch's face reaches the axis; the die's and holder's faces
      // reach past the sheet. Walls: the punch's and die's over the stroke,
      // the holder's over its edge radius.
      const double a_max = unbounded    ? 0.
                           : side_a < 0 ? inradius
                                        : std::max(extent.reach - outline, R);
      const double b_max =
        side_b < 0 || side_a < 0 ? extent.wall : R + 0.25 * extent.wall;
      std::vector<std::pair<double, double>> ab;
      if (unbounded)
        for (unsigned int i = 0; i <= n_side; ++i)
          ab.emplace_back(extent.reach * (n_side - i) / n_side, 0.);
      else
        ab = profile(a_max, R, b_max);

      ToolSurface<dim> s;
      std::size_t      width = 0; // points per ring
      for (const auto &[a, b] : ab)
        {
          const double rho = unbounded ? a : side_a * a;
          const double z   = z_face + side_b * b + offset[dim - 1];
          if constexpr (dim == 2)
            {
              const double r = unbounded ? rho : planform.radius + rho;
              s.points.emplace_back(std::max(r, 0.) + offset[0], z);
              width = 1;
            }
          else
            {
              const auto points = ring(quadrant_outline(planform, rho), extent);
              width             = points.size();
              for (const auto &p : points)
                s.points.emplace_back(p[0] + offset[0], p[1] + offset[1], z);
            }
        }
      const unsigned int n_rings = ab.size();
      for (unsigned int k = 0; k + 1 < n_rings; ++k)
        {
          if constexpr (dim == 2)
            s.cells.push_back({{k, k + 1}});
          else
            {
              const bool closed =
                extent.last_angle - extent.first_angle >= 360 - 1e-9;
              const unsigned int n = width, m = closed ? n : n - 1;
              for (unsigned int j = 0; j < m; ++j)
                {
                  const unsigned int j1 = (j + 1) % n;
                  s.cells.push_back({{k * n + j,
                                      k * n + j1,
                                      (k + 1) * n + j,
                                      (k + 1) * n + j1}});
                }
            }
        }
      return s;
    }

#define INSTANTIATE(dim)                                                     \
  template ToolSurface<dim> ProfileTool<dim>::surface(const SurfaceExtent &) \
    const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace tools
} // namespace formsolve
