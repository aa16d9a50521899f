// A triangulated tool surface (from CAD: STL, gmsh) and the query contact
// needs: the signed distance, closest point and normal of a point. The
// closest point comes from CGAL's AABB tree; the sign from the angle-weighted
// pseudonormal of the face, edge or vertex it lies on (Baerentzen and Aanaes,
// doc/theory.md), which decides it at edges and vertices as well as inside
// faces, for closed and open surfaces alike.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <formsolve/tools/surface_file.h>

#include <memory>

namespace formsolve
{
  namespace tools
  {
    class TriangleSurface
    {
    public:
      /// Checks the mesh (triangles, consistent orientation, no edge shared
      /// by more than two triangles) and builds the search tree. @p name
      /// (the file) is named in every error. Neighbours whose normals differ
      /// by more than @p feature_angle (degrees) meet at a sharp edge.
      TriangleSurface(const SurfaceMesh &mesh,
                      const std::string &name,
                      const double       feature_angle = 30);
      ~TriangleSurface();

      struct Query
      {
        /// Positive on the working side, negative behind the surface (mm).
        double   distance = 0;
        Point<3> closest;
        /// Unit normal of the surface at the closest point, towards the
        /// working side.
        Tensor<1, 3> normal;
        unsigned int triangle = 0;
      };
      /// Whether any triangle meets the cube of half-size @p reach about
      /// @p p (every point within @p reach of the surface has one).
      bool near(const Point<3> &p, const double reach) const;
      /// The triangles as they are (exact distance to the facets).
      Query closest(const Point<3> &p) const;
      /// The smooth surface the triangles stand for: normals interpolated
      /// from the vertices and the facet lifted by Phong's quadratic
      /// (doc/theory.md eq. 7b), except at sharp edges and boundaries,
      /// where the facets are exact.
      Query smooth(const Point<3> &p) const;

      unsigned int n_triangles() const { return faces.size(); }
      /// Edges with one triangle only: 0 for a closed surface.
      unsigned int n_boundary_edges() const { return boundary_edges; }
      /// The triangles at an edge whose curvature radius (dihedral angle
      /// over the distance of the triangles' centres) is below @p radius
      /// (mm), or at a sharp edge: where the sheet bends over the tool.
      SurfaceMesh curved_part(const double radius) const;
      /// The area, projected on the plane z = @p z, of the triangles seen
      /// from that plane along z (nothing of the surface in between):
      /// counted positive where their normals point towards the plane.
      double                       area_seen_from(const double z) const;
      const std::vector<Point<3>> &points() const { return vertices; }
      const std::vector<std::array<unsigned int, 3>> &triangles() const
      {
        return faces;
      }

    private:
      /// The vertex normal of each corner from its @p group (the corners
      /// 3 f + k joined across smooth edges, by their group's first index).
      void set_corner_normals(const std::vector<unsigned int> &group);
      /// Barycentric coordinates of @p x in triangle @p f.
      std::array<double, 3> barycentric(const unsigned int f,
                                        const Point<3>    &x) const;

      struct Tree; // CGAL, kept out of this header
      std::unique_ptr<Tree>                    tree;
      std::vector<Point<3>>                    vertices;
      std::vector<std::array<unsigned int, 3>> faces;
      std::vector<Tensor<1, 3>>                face_normal, vertex_normal;
      /// Per triangle, the pseudonormals of its edges (v0v1, v1v2, v2v0).
      std::vector<std::array<Tensor<1, 3>, 3>> edge_normal;
      /// Per triangle, its neighbour across each edge (or none).
      std::vector<std::array<unsigned int, 3>> neighbour;
      /// Per triangle and corner, the normal of the vertex on this side of
      /// any sharp edge through it.
      std::vector<std::array<Tensor<1, 3>, 3>> corner_normal;
      std::vector<std::array<bool, 3>>         sharp_edge;
      std::vector<bool>                        sharp_vertex;
      unsigned int                             boundary_edges = 0;
    };

  } // namespace tools
} // namespace formsolve
