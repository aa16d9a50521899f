#include <formsolve/model/dimensions.h>
#include <formsolve/tools/profile_tool.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    double rounded_quadrant_distance(const double a,
                                     const double b,
                                     const double R,
                                     double      &ga,
                                     double      &gb)
    {
      // The rounded quadrant is the quadrant shrunk by R and dilated by R:
      // its signed distance is that of the shrunk quadrant minus R.
      const double as = a - R, bs = b - R;
      if (as >= 0 && bs >= 0) // deep inside: nearest face
        {
          if (as < bs)
            ga = -1, gb = 0;
          else
            ga = 0, gb = -1;
          return -std::min(as, bs) - R;
        }
      if (as < 0 && bs < 0) // around the rounded edge
        {
          const double d = std::sqrt(as * as + bs * bs);
          if (d > 0)
            ga = as / d, gb = bs / d;
          else
            ga = gb = -std::sqrt(0.5);
          return d - R;
        }
      if (as < 0) // beside the wall a = 0
        {
          ga = -1, gb = 0;
          return -a;
        }
      ga = 0, gb = -1; // beside the face b = 0
      return -b;
    }

    template <int dim>
    double Planform<dim>::distance(const Point<dim> &p, Tensor<1, dim> &g) const
    {
      g = 0;
      switch (kind)
        {
          case Kind::unbounded:
            return -std::numeric_limits<double>::max() / 4;
          case Kind::circle:
            {
              double r2 = 0;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                r2 += p[d] * p[d];
              const double r = std::sqrt(r2);
              if (r > 0)
                for (unsigned int d = 0; d + 1 < dim; ++d)
                  g[d] = p[d] / r;
              else
                g[0] = 1;
              return r - radius;
            }
          case Kind::rounded_rectangle:
            {
              const double half[2] = {half_length, half_width};
              double       q[2], s[2];
              for (unsigned int d = 0; d < 2 && d + 1 < dim; ++d)
                {
                  s[d] = (p[d] >= 0 ? 1. : -1.);
                  q[d] = std::abs(p[d]) - (half[d] - corner_radius);
                }
              if (dim == 2)
                {
                  g[0] = s[0];
                  return q[0] - corner_radius;
                }
              if (q[0] > 0 && q[1] > 0)
                {
                  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1]);
                  g[0]           = s[0] * q[0] / n;
                  g[1]           = s[1] * q[1] / n;
                  return n - corner_radius;
                }
              if (q[0] > q[1])
                {
                  g[0] = s[0];
                  return q[0] - corner_radius;
                }
              g[1] = s[1];
              return q[1] - corner_radius;
            }
        }
      return 0;
    }

    template <int dim>
    ProfileTool<dim>::ProfileTool(const std::string    &name,
                                  const Planform<dim>  &planform,
                                  const int             side_a,
                                  const int             side_b,
                                  const double          z_face,
                                  const double          profile_radius,
                                  const Tensor<1, dim> &velocity)
        : tool_name(name)
        , planform(planform)
        , side_a(side_a)
        , side_b(side_b)
        , z_face(z_face)
        , profile_radius(profile_radius)
        , tool_velocity(velocity)
    {}

    template <int dim>
    double ProfileTool<dim>::signed_distance(const Point<dim> &x,
                                             Tensor<1, dim>   &normal) const
    {
      const Point<dim> p = x - offset;
      Tensor<1, dim>   grad_rho;
      const double     rho = planform.distance(p, grad_rho);
      double           a   = side_a * rho;
      if (planform.kind == Planform<dim>::Kind::unbounded)
        a = std::numeric_limits<double>::max() / 4; // the face has no edge
      const double b = side_b * (p[dim - 1] - z_face);
      double       ga, gb;
      const double d = rounded_quadrant_distance(a, b, profile_radius, ga, gb);
      normal         = (ga * side_a) * grad_rho;
      normal[dim - 1] += gb * side_b;
      return d;
    }

    template <int dim>
    double ProfileTool<dim>::distance_to_radius(const Point<dim> &x) const
    {
      if (planform.kind == Planform<dim>::Kind::unbounded)
        return std::numeric_limits<double>::infinity();
      // In the (a, b) section the arc is the quarter circle of radius R about
      // (R, R) between (0, R) and (R, 0).
      const Point<dim> p = x - offset;
      Tensor<1, dim>   grad_rho;
      const double     a  = side_a * planform.distance(p, grad_rho);
      const double     b  = side_b * (p[dim - 1] - z_face);
      const double     R  = profile_radius;
      const double     as = a - R, bs = b - R;
      if (as <= 0 && bs <= 0)
        return std::abs(std::sqrt(as * as + bs * bs) - R);
      return std::min(std::hypot(a, b - R), std::hypot(a - R, b));
    }

    template <int dim>
    double ProfileTool<dim>::lateral_distance(const Point<dim> &x) const
    {
      if (planform.kind == Planform<dim>::Kind::unbounded)
        return std::numeric_limits<double>::infinity();
      Tensor<1, dim> grad_rho;
      return side_a * planform.distance(x - offset, grad_rho);
    }

    template <int dim>
    void ProfileTool<dim>::advance(const double dt)
    {
      offset += dt * tool_velocity;
      travelled += dt * tool_velocity.norm();
    }

#define INSTANTIATE(dim)         \
  template struct Planform<dim>; \
  template class ProfileTool<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace tools
} // namespace formsolve
