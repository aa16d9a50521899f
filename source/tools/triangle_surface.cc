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

      /// The interior angle of triangle t at its corner k.
      double corner_angle(const std::vector<Point<3>>       &x,
                          const std::array<unsigned int, 3> &t,
                          const unsigned int                 k)
      {
        const Tensor<1, 3> a = x[t[(k + 1) % 3]] - x[t[k]];
        const Tensor<1, 3> b = x[t[(k + 2) % 3]] - x[t[k]];
        return std::acos(std::clamp(a * b / (a.norm() * b.norm()), -1., 1.));
      }
    } // namespace

    struct TriangleSurface::Tree
    {
      std::vector<Triangle> triangles;
      AabbTree              tree;
    };

    TriangleSurface::TriangleSurface(const SurfaceMesh &mesh,
                                     const std::string &name)
        : tree(std::make_unique<Tree>())
        , vertices(mesh.vertices)
    {
      // Degenerate triangles (no area) carry no normal: left out.
      double size = 0;
      for (const auto &v : vertices)
        size = std::max(size, v.norm());
      for (const auto &t : mesh.triangles)
        {
          for (const auto v : t)
            AssertThrow(v < vertices.size(),
                        ExcMessage(name + ": a triangle refers to a "
                                          "missing vertex"));
          const Tensor<1, 3> n =
            cross_product_3d(vertices[t[1]] - vertices[t[0]],
                             vertices[t[2]] - vertices[t[0]]);
          if (n.norm() > 1e-14 * (size * size + 1e-300))
            {
              faces.push_back(t);
              face_normal.push_back(n / n.norm());
            }
        }
      AssertThrow(!faces.empty(),
                  ExcMessage(name + ": no triangle with an area"));

      // Orientation: a directed edge used twice means two neighbours whose
      // normals point to opposite sides; three triangles on one edge have
      // no side at all.
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
                          "share that edge; orient the surface so that every "
                          "normal points to the working side"));
            directed[e] = f;
          }

      vertex_normal.assign(vertices.size(), Tensor<1, 3>());
      edge_normal.resize(faces.size());
      for (unsigned int f = 0; f < faces.size(); ++f)
        for (unsigned int k = 0; k < 3; ++k)
          {
            vertex_normal[faces[f][k]] +=
              corner_angle(vertices, faces[f], k) * face_normal[f];
            const auto twin =
              directed.find({faces[f][(k + 1) % 3], faces[f][k]});
            edge_normal[f][k] = face_normal[f];
            if (twin != directed.end())
              edge_normal[f][k] += face_normal[twin->second];
            else
              ++boundary_edges;
          }
      for (auto &n : vertex_normal)
        if (n.norm() > 0)
          n /= n.norm();

      for (const auto &t : faces)
        tree->triangles.emplace_back(cgal(vertices[t[0]]),
                                     cgal(vertices[t[1]]),
                                     cgal(vertices[t[2]]));
      tree->tree.insert(tree->triangles.cbegin(), tree->triangles.cend());
      tree->tree.build();
      tree->tree.accelerate_distance_queries();
    }

    TriangleSurface::~TriangleSurface() = default;

    TriangleSurface::Query TriangleSurface::closest(const Point<3> &p) const
    {
      const auto hit = tree->tree.closest_point_and_primitive(cgal(p));
      Query      q;
      q.triangle = hit.second - tree->triangles.cbegin();
      q.closest  = Point<3>(hit.first.x(), hit.first.y(), hit.first.z());

      // Where in the triangle the closest point lies (barycentric
      // coordinates) decides whose pseudonormal gives the side.
      const auto        &t            = faces[q.triangle];
      const Tensor<1, 3> e1           = vertices[t[1]] - vertices[t[0]],
                         e2           = vertices[t[2]] - vertices[t[0]],
                         r            = q.closest - vertices[t[0]];
      const double                d11 = e1 * e1, d12 = e1 * e2, d22 = e2 * e2;
      const double                det = d11 * d22 - d12 * d12;
      const double                b1  = (d22 * (r * e1) - d12 * (r * e2)) / det;
      const double                b2  = (d11 * (r * e2) - d12 * (r * e1)) / det;
      const std::array<double, 3> w   = {{1 - b1 - b2, b1, b2}};
      constexpr double            tol = 1e-10;
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
  } // namespace tools
} // namespace formsolve
