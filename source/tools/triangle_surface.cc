#include <deal.II/base/exceptions.h>

#include <formsolve/tools/triangle_surface.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      using Kernel    = CGAL::Simple_cartesian<double>;
      using Triangle  = Kernel::Triangle_3;
      using Iterator  = std::vector<Triangle>::const_iterator;
      using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
      using AabbTree  = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

      Kernel::Point_3 cgal(const Point<3> &p)
      {
        return {p[0], p[1], p[2]};
      }

      std::string where(const Point<3> &p)
      {
        std::ostringstream s;
        s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
        return s.str();
      }

      /// Max's weighting of a face normal at a corner, (e1 x e2) / (|e1|^2
      /// |e2|^2): exact vertex normals for vertices on a sphere (N. Max,
      /// J. Graphics Tools 4(2), 1999).
      Tensor<1, 3> max_weighted(const std::vector<Point<3>>       &x,
                                const std::array<unsigned int, 3> &t,
                                const unsigned int                 k)
      {
        const Tensor<1, 3> a = x[t[(k + 1) % 3]] - x[t[k]];
        const Tensor<1, 3> b = x[t[(k + 2) % 3]] - x[t[k]];
        return cross_product_3d(a, b) / (a.norm_square() * b.norm_square());
      }

      /// The interior angle of triangle t at its corner k.
      double corner_angle(const std::vector<Point<3>>       &x,
                          const std::array<unsigned int, 3> &t,
                          const unsigned int                 k)
      {
        const Tensor<1, 3> a = x[t[(k + 1) % 3]] - x[t[k]];
        const Tensor<1, 3> b = x[t[(k + 2) % 3]] - x[t[k]];
        return std::acos(std::clamp(a * b / (a.norm() * b.norm()), -1., 1.));
      }
      /// Each directed edge (v0, v1) of the triangles, as 3 f + k. A
      /// directed edge used twice means two neighbours whose normals point
      /// to opposite sides; three triangles on one edge have no side at all.
      std::map<std::pair<unsigned int, unsigned int>, unsigned int>
      directed_edges(const std::vector<Point<3>>                    &vertices,
                     const std::vector<std::array<unsigned int, 3>> &faces,
                     const std::string                              &name)
      {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> directed;
        for (unsigned int f = 0; f < faces.size(); ++f)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const auto e = std::make_pair(faces[f][k], faces[f][(k + 1) % 3]);
              AssertThrow(directed.count(e) == 0,
                          ExcMessage(
                            name +
                            ": the triangles are not consistently "
                            "oriented (two neighbours at the edge from " +
                            where(vertices[e.first]) + " to " +
                            where(vertices[e.second]) +
                            " point to opposite sides), or three triangles "
                            "share that edge; orient the surface so that "
                            "every normal points to the working side"));
              directed[e] = 3 * f + k;
            }
        return directed;
      }
    } // namespace

    struct TriangleSurface::Tree
    {
      std::vector<Triangle> triangles;
      AabbTree              tree;
    };

    TriangleSurface::TriangleSurface(const SurfaceMesh &mesh,
                                     const std::string &name,
                                     const double       feature_angle)
        : tree(std::make_unique<Tree>())
        , vertices(mesh.vertices)
    {
      // Triangles without area carry no normal: left out (orient() has
      // said so for surfaces from files).
      for (const auto &t : mesh.triangles)
        {
          for (const auto v : t)
            AssertThrow(v < vertices.size(),
                        ExcMessage(name + ": a triangle refers to a "
                                          "missing vertex"));
          if (has_area(mesh, t))
            {
              const Tensor<1, 3> n =
                cross_product_3d(vertices[t[1]] - vertices[t[0]],
                                 vertices[t[2]] - vertices[t[0]]);
              faces.push_back(t);
              face_normal.push_back(n / n.norm());
            }
        }
      AssertThrow(!faces.empty(),
                  ExcMessage(name + ": no triangle with an area"));

      const auto directed = directed_edges(vertices, faces, name);

      constexpr unsigned int none = static_cast<unsigned int>(-1);
      vertex_normal.assign(vertices.size(), Tensor<1, 3>());
      edge_normal.resize(faces.size());
      neighbour.assign(faces.size(), {{none, none, none}});
      sharp_edge.assign(faces.size(), {{false, false, false}});
      sharp_vertex.assign(vertices.size(), false);
      // Corners joined across smooth edges share one vertex normal
      // (union-find over the corners 3 f + k).
      std::vector<unsigned int> group(3 * faces.size());
      for (unsigned int c = 0; c < group.size(); ++c)
        group[c] = c;
      const auto root = [&](unsigned int c) {
        while (group[c] != c)
          c = group[c] = group[group[c]];
        return c;
      };
      const double cos_feature = std::cos(feature_angle * M_PI / 180);
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (unsigned int k = 0; k < 3; ++k)
          {
            vertex_normal[faces[f][k]] +=
              corner_angle(vertices, faces[f], k) * face_normal[f];
            const auto twin =
              directed.find({faces[f][(k + 1) % 3], faces[f][k]});
            edge_normal[f][k] = face_normal[f];
            if (twin == directed.end())
              {
                ++boundary_edges;
                sharp_edge[f][k] = true;
                continue;
              }
            const unsigned int g = twin->second / 3, j = twin->second % 3;
            neighbour[f][k] = g;
            edge_normal[f][k] += face_normal[g];
            sharp_edge[f][k] = face_normal[f] * face_normal[g] < cos_feature;
            if (!sharp_edge[f][k])
              {
                // g runs from faces[f][k + 1] (its corner j) to faces[f][k].
                group[root(3 * f + k)]           = root(3 * g + (j + 1) % 3);
                group[root(3 * f + (k + 1) % 3)] = root(3 * g + j);
              }
          }
      for (auto &n : vertex_normal)
        if (n.norm() > 0)
          n /= n.norm();
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (unsigned int k = 0; k < 3; ++k)
          if (sharp_edge[f][k])
            sharp_vertex[faces[f][k]] = sharp_vertex[faces[f][(k + 1) % 3]] =
              true;
      for (unsigned int c = 0; c < group.size(); ++c)
        group[c] = root(c);
      set_corner_normals(group);

      for (const auto &t : faces)
        tree->triangles.emplace_back(cgal(vertices[t[0]]),
                                     cgal(vertices[t[1]]),
                                     cgal(vertices[t[2]]));
      tree->tree.insert(tree->triangles.cbegin(), tree->triangles.cend());
      tree->tree.build();
      tree->tree.accelerate_distance_queries();
    }

    TriangleSurface::~TriangleSurface() = default;

    void
    TriangleSurface::set_corner_normals(const std::vector<unsigned int> &group)
    {
      std::vector<Tensor<1, 3>> normal(group.size());
      for (unsigned int c = 0; c < group.size(); ++c)
        normal[group[c]] += max_weighted(vertices, faces[c / 3], c % 3);
      // Where a plane meets a curved part tangentially (a tool's face and
      // its radius) the normal is the plane's: a vertex whose group has
      // coplanar triangles filling at least 150 degrees on one side only
      // takes their normal, which keeps the plane flat up to the tangent
      // line. (Two such planes: a fold, or a column of facets on a
      // cylinder, where the mean is right.)
      std::vector<std::vector<unsigned int>> members(group.size());
      for (unsigned int c = 0; c < group.size(); ++c)
        members[group[c]].push_back(c);
      for (unsigned int g = 0; g < group.size(); ++g)
        {
          std::vector<Tensor<1, 3>> planes;
          for (const unsigned int c : members[g])
            {
              const Tensor<1, 3> &n     = face_normal[c / 3];
              double              angle = 0;
              for (const unsigned int d : members[g])
                if ((face_normal[d / 3] - n).norm() < 1e-6)
                  angle += corner_angle(vertices, faces[d / 3], d % 3);
              if (angle >= 150 * M_PI / 180 &&
                  std::none_of(planes.begin(),
                               planes.end(),
                               [&](const Tensor<1, 3> &m) {
                                 return (m - n).norm() < 1e-6;
                               }))
                planes.push_back(n);
            }
          if (planes.size() == 1)
            normal[g] = planes[0];
        }
      corner_normal.resize(faces.size());
      for (unsigned int c = 0; c < group.size(); ++c)
        corner_normal[c / 3][c % 3] =
          normal[group[c]] / normal[group[c]].norm();
    }

    std::array<double, 3> TriangleSurface::barycentric(const unsigned int f,
                                                       const Point<3> &x) const
    {
      const auto        &t  = faces[f];
      const Tensor<1, 3> e1 = vertices[t[1]] - vertices[t[0]],
                         e2 = vertices[t[2]] - vertices[t[0]],
                         r  = x - vertices[t[0]];
      const double d11 = e1 * e1, d12 = e1 * e2, d22 = e2 * e2;
      const double det = d11 * d22 - d12 * d12;
      const double b1  = (d22 * (r * e1) - d12 * (r * e2)) / det;
      const double b2  = (d11 * (r * e2) - d12 * (r * e1)) / det;
      return {{1 - b1 - b2, b1, b2}};
    }

    bool TriangleSurface::near(const Point<3> &p, const double reach) const
    {
      const Kernel::Iso_cuboid_3 box(
        cgal(p - Tensor<1, 3>({reach, reach, reach})),
        cgal(p + Tensor<1, 3>({reach, reach, reach})));
      return tree->tree.do_intersect(box);
    }

    TriangleSurface::Query TriangleSurface::closest(const Point<3> &p) const
    {
      const auto hit = tree->tree.closest_point_and_primitive(cgal(p));
      Query      q;
      q.triangle = hit.second - tree->triangles.cbegin();
      q.closest  = Point<3>(hit.first.x(), hit.first.y(), hit.first.z());

      // Where in the triangle the closest point lies (barycentric
      // coordinates) decides whose pseudonormal gives the side.
      const auto                 &t     = faces[q.triangle];
      const std::array<double, 3> w     = barycentric(q.triangle, q.closest);
      constexpr double            tol   = 1e-10;
      Tensor<1, 3>                side  = face_normal[q.triangle];
      unsigned int                zeros = 0;
      for (unsigned int k = 0; k < 3; ++k)
        zeros += w[k] < tol;
      if (zeros >= 2) // a corner: the one with the weight
        side =
          vertex_normal[t[std::max_element(w.begin(), w.end()) - w.begin()]];
      else if (zeros == 1) // an edge: the one opposite the zero weight
        {
          const unsigned int k =
            std::min_element(w.begin(), w.end()) - w.begin();
          side = edge_normal[q.triangle][(k + 1) % 3];
        }

      const Tensor<1, 3> away   = p - q.closest;
      const double       sign   = away * side < 0 ? -1. : 1.;
      const double       length = away.norm();
      q.distance                = sign * length;
      q.normal = length > 1e-12 * (1 + p.norm()) ? sign * away / length
                                                 : side / side.norm();
      return q;
    }

    TriangleSurface::Query TriangleSurface::smooth(const Point<3> &p) const
    {
      Query                       q = closest(p);
      const unsigned int          f = q.triangle;
      const std::array<double, 3> w = barycentric(f, q.closest);
      // On a sharp edge or at a vertex of one the facets are the surface.
      constexpr double tol   = 1e-10;
      unsigned int     zeros = 0;
      for (unsigned int k = 0; k < 3; ++k)
        zeros += w[k] < tol;
      const unsigned int big = std::max_element(w.begin(), w.end()) - w.begin(),
                         small =
                           std::min_element(w.begin(), w.end()) - w.begin();
      if ((zeros >= 2 && sharp_vertex[faces[f][big]]) ||
          (zeros == 1 && sharp_edge[f][(small + 1) % 3]))
        return q;
      // Phong's quadratic with shape factor 1/2, which lies on a circle or
      // sphere through the vertices with their normals to second order:
      // the facet point lifted by half the mean of its offsets from the
      // vertices' tangent planes.
      Tensor<1, 3> n;
      Point<3>     lifted = q.closest;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const Tensor<1, 3> &nk = corner_normal[f][k];
          n += w[k] * nk;
          lifted +=
            0.5 * w[k] * ((vertices[faces[f][k]] - q.closest) * nk) * nk;
        }
      n /= n.norm();
      q.closest  = lifted;
      q.normal   = n;
      q.distance = (p - lifted) * n;
      return q;
    }

    double TriangleSurface::area_seen_from(const double z) const
    {
      double size = 0;
      for (const auto &v : vertices)
        size = std::max(size, v.norm());
      double seen = 0;
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          const auto    &t = faces[f];
          const Point<3> c((vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) /
                           3.);
          const double   to_plane = z - c[2];
          const double   projected =
            0.5 * cross_product_3d(vertices[t[1]] - vertices[t[0]],
                                   vertices[t[2]] - vertices[t[0]])[2];
          if (std::abs(to_plane) < 1e-9 * size || projected == 0)
            continue;
          // The segment from just off the triangle to the plane.
          const double   step = 1e-9 * size * (to_plane > 0 ? 1 : -1);
          const Point<3> a(c[0], c[1], c[2] + step), b(c[0], c[1], z);
          if (tree->tree.do_intersect(Kernel::Segment_3(cgal(a), cgal(b))))
            continue;
          // n_z dA, times the sign of the direction to the plane.
          seen += (to_plane > 0 ? 1 : -1) * projected;
        }
      return seen;
    }

    SurfaceMesh TriangleSurface::curved_part(const double radius) const
    {
      SurfaceMesh part;
      part.vertices = vertices;
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          bool curved = false;
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int g = neighbour[f][k];
              if (sharp_edge[f][k] && g != static_cast<unsigned int>(-1))
                curved = true;
              else if (g != static_cast<unsigned int>(-1))
                {
                  const double angle = std::acos(
                    std::clamp(face_normal[f] * face_normal[g], -1., 1.));
                  Tensor<1, 3> between;
                  for (unsigned int c = 0; c < 3; ++c)
                    between += (vertices[faces[f][c]] - vertices[faces[g][c]]);
                  curved |= angle * radius > between.norm() / 3;
                }
            }
          if (curved)
            part.triangles.push_back(faces[f]);
        }
      return part;
    }
  } // namespace tools
} // namespace formsolve
