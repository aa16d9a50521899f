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
      /// (the file) is named in every error.
      TriangleSurface(const SurfaceMesh &mesh, const std::string &name);
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
      Query closest(const Point<3> &p) const;

      unsigned int n_triangles() const { return faces.size(); }
      /// Edges with one triangle only: 0 for a closed surface.
      unsigned int n_boundary_edges() const { return boundary_edges; }

    private:
      struct Tree; // CGAL, kept out of this header
      std::unique_ptr<Tree>                    tree;
      std::vector<Point<3>>                    vertices;
      std::vector<std::array<unsigned int, 3>> faces;
      std::vector<Tensor<1, 3>>                face_normal, vertex_normal;
      /// Per triangle, the pseudonormals of its edges (v0v1, v1v2, v2v0).
      std::vector<std::array<Tensor<1, 3>, 3>> edge_normal;
      unsigned int                             boundary_edges = 0;
    };

  } // namespace tools
} // namespace formsolve
