#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/parameters/require.h>
#include <formsolve/tools/profile_file.h>
#include <formsolve/tools/triangle_surface.h>
#include <formsolve/trimming/trim_shape.h>

#include <cmath>
#include <limits>

namespace formsolve
{
  namespace trimming
  {
    using namespace dealii;

    namespace
    {
      /// The object rank 0 made by @p read, on every rank; an error on rank
      /// 0 is thrown on every rank.
      template <typename T, typename Read>
      T read_on_root(MPI_Comm comm, const Read &read)
      {
        std::pair<T, std::string> got;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              got.first = read();
            }
          catch (const std::exception &e)
            {
              got.second = e.what();
            }
        got = Utilities::MPI::broadcast(comm, got, 0);
        AssertThrow(got.second.empty(), ExcMessage(got.second));
        return got.first;
      }
    } // namespace

    template <int dim>
    TrimShape<dim>::TrimShape(const parameters::Trimming &t,
                              const model::Model          m,
                              MPI_Comm                    comm)
        : curve_keeps(t.curve_side)
        , surface_keeps(t.surface_side)
    {
      const auto names = model::coordinate_names(m);
      for (const auto &c : t.planes)
        {
          Plane p{Tensor<1, dim>(), c.value};
          for (const auto &[letter, a] : c.terms)
            for (unsigned int d = 0; d < dim; ++d)
              if (names[d][0] == letter)
                p.normal[d] += a;
          const double n = p.normal.norm();
          Assert(n > 0, ExcInternalError()); // check_trimming's
          const double s = c.keep_greater ? 1 : -1;
          p.normal *= s / n;
          p.offset *= s / n;
          planes.push_back(p);
        }
      if (!t.curve_file.empty())
        {
          const auto lines = read_on_root<tools::ProfileLines>(comm, [&]() {
            return tools::read_profile_csv(t.curve_file,
                                           "Trimming/Curve file",
                                           "x, y",
                                           false);
          });
          curve            = lines.points;
          parameters::require(curve.size() >= 2,
                              "Trimming/Curve file",
                              t.curve_file + " has fewer than 2 points");
          closed = curve.size() > 3 && curve.front().distance(curve.back()) <=
                                         1e-9 * (1 + curve.front().norm());
          const bool around = curve_keeps == parameters::CurveSide::inside ||
                              curve_keeps == parameters::CurveSide::outside;
          parameters::require(
            around == closed,
            "Trimming/Curve keeps",
            closed ? "the curve in " + t.curve_file +
                       " is closed (its last point is its first): it keeps "
                       "inside or outside, not left or right"
                   : "the curve in " + t.curve_file +
                       " is open (its last point is not its first): it "
                       "keeps left or right, not inside or outside");
        }
      if (!t.surface_file.empty())
        {
          const auto mesh = read_on_root<tools::SurfaceMesh>(comm, [&]() {
            return tools::read_surface(t.surface_file, t.tolerance);
          });
          surface =
            std::make_unique<tools::TriangleSurface>(mesh, t.surface_file);
        }
    }

    template <int dim>
    TrimShape<dim>::~TrimShape() = default;

    template <int dim>
    double TrimShape<dim>::curve_side(const Point<2> &p) const
    {
      // The left normal of segment i (unnormalised length: the segment's).
      const auto left = [this](const unsigned int i) {
        const Tensor<1, 2> d = curve[i + 1] - curve[i];
        return Tensor<1, 2>({-d[1], d[0]}) / std::max(d.norm(), 1e-300);
      };
      double       nearest = std::numeric_limits<double>::max();
      unsigned int at      = 0;   // the nearest segment
      double       along   = 0.5; // where on it (0..1)
      int          winding = 0;
      const auto   n       = curve.size();
      for (unsigned int i = 0; i + 1 < n; ++i)
        {
          const Point<2>    &a = curve[i], &b = curve[i + 1];
          const Tensor<1, 2> d = b - a, w = p - a;
          const double       L2 = d * d;
          const double       s = L2 > 0 ? std::clamp((w * d) / L2, 0., 1.) : 0.;
          if (const double dist = (p - (a + s * d)).norm(); dist < nearest)
            {
              nearest = dist;
              at      = i;
              along   = s;
            }
          // Winding number (Sunday's crossing rule).
          const double cross = d[0] * w[1] - d[1] * w[0];
          if (a[1] <= p[1] && b[1] > p[1] && cross > 0)
            ++winding;
          else if (a[1] > p[1] && b[1] <= p[1] && cross < 0)
            --winding;
        }
      // The side of an open curve: the nearest segment's, or at a vertex
      // between two segments the mean of their normals' (which decides
      // points in the wedge outside a bend).
      Tensor<1, 2> normal = left(at);
      if (along <= 0 && at > 0)
        normal += left(at - 1);
      else if (along >= 1 && at + 2 < n)
        normal += left(at + 1);
      const Point<2> foot = curve[at] + along * (curve[at + 1] - curve[at]);
      const double   sign = (p - foot) * normal >= 0 ? 1 : -1;
      using parameters::CurveSide;
      switch (curve_keeps)
        {
          case CurveSide::inside:
            return winding != 0 ? nearest : -nearest;
          case CurveSide::outside:
            return winding != 0 ? -nearest : nearest;
          case CurveSide::left:
            return sign * nearest;
          case CurveSide::right:
            return -sign * nearest;
        }
      return nearest;
    }

    template <int dim>
    double TrimShape<dim>::side(const Point<dim> &p) const
    {
      double s = std::numeric_limits<double>::max();
      for (const auto &c : planes)
        s = std::min(s, c.normal * p - c.offset);
      if constexpr (dim == 3)
        {
          if (!curve.empty())
            s = std::min(s, curve_side(Point<2>(p[0], p[1])));
          if (surface)
            {
              const double d = surface->closest(p).distance;
              s =
                std::min(s,
                         surface_keeps == parameters::SurfaceSide::behind ? -d
                                                                          : d);
            }
        }
      return s;
    }

#define INSTANTIATE(dim) template class TrimShape<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace trimming
} // namespace formsolve
