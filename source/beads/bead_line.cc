#include <formsolve/beads/bead_line.h>
#include <formsolve/model/dimensions.h>

#include <cmath>

namespace formsolve
{
  namespace beads
  {
    using namespace dealii;

    namespace
    {
      /// The part [lo, hi] of the segment a + s (b - a), 0 <= s <= 1, that
      /// lies in the modelled part of a 3-D model (x >= 0 with a symmetry
      /// plane x = 0, likewise y; y <= @p width for the slice): the line
      /// force is integrated exactly up to the symmetry planes.
      std::pair<double, double> clip(const std::pair<double, double> &a,
                                     const std::pair<double, double> &b,
                                     const model::Model               m,
                                     const double                     width)
      {
        double lo = 0, hi = 1;
        // Keeps s where c + s d >= 0.
        auto keep = [&](const double c, const double d) {
          if (d == 0)
            {
              if (c < 0)
                hi = -1;
              return;
            }
          const double s0 = -c / d;
          if (d > 0)
            lo = std::max(lo, s0);
          else
            hi = std::min(hi, s0);
        };
        if (model::symmetric_in_x(m))
          keep(a.first, b.first - a.first);
        if (model::symmetric_in_y(m))
          keep(a.second, b.second - a.second);
        if (m == model::Model::slice)
          keep(width - a.second, a.second - b.second);
        return {lo, hi};
      }
    } // namespace

    template <int dim>
    std::vector<BeadPoint<dim>> bead_points(const parameters::DrawBead   &bead,
                                            const model::Kinematics<dim> &k,
                                            const double                  piece,
                                            const model::Model            m,
                                            const double slice_width)
    {
      std::vector<BeadPoint<dim>> points;
      if (dim == 2)
        {
          // A round bead in the r-z section or a straight one across the
          // strip: one point, the ring or the width its length.
          BeadPoint<dim> p;
          p.plan[0]   = bead.line[0].first;
          p.weight    = k.volume_factor(p.plan);
          p.normal[0] = 1;
          p.along     = 0;
          points.push_back(p);
          return points;
        }
      const double total = bead.length();
      const double gauss = 0.5 / std::sqrt(3.);
      double       done  = 0;
      const auto   n     = bead.line.size();
      for (std::size_t i = 0; i + 1 < n + (bead.closed ? 1 : 0); ++i)
        {
          const auto  &a = bead.line[i], &b = bead.line[(i + 1) % n];
          const double dx = b.first - a.first, dy = b.second - a.second;
          const double length = std::hypot(dx, dy);
          const auto [lo, hi] = clip(a, b, m, slice_width);
          if (length == 0 || hi <= lo)
            {
              done += length;
              continue;
            }
          const double       part = (hi - lo) * length;
          const unsigned int pieces =
            std::max(1u, static_cast<unsigned int>(std::ceil(part / piece)));
          for (unsigned int j = 0; j < pieces; ++j)
            for (const double g : {0.5 - gauss, 0.5 + gauss})
              {
                const double   s = lo + (hi - lo) * (j + g) / pieces;
                BeadPoint<dim> p;
                p.plan[0]   = a.first + s * dx;
                p.plan[1]   = a.second + s * dy;
                p.weight    = 0.5 * part / pieces;
                p.normal[0] = dy / length; // to the right of the way
                p.normal[1] = -dx / length;
                p.along     = (done + s * length) / total;
                points.push_back(p);
              }
          done += length;
        }
      return points;
    }

#define INSTANTIATE(dim)                                 \
  template std::vector<BeadPoint<dim>> bead_points<dim>( \
    const parameters::DrawBead &,                        \
    const model::Kinematics<dim> &,                      \
    double,                                              \
    model::Model,                                        \
    double);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace beads
} // namespace formsolve
