// Where the beads' lines cross the sheet: for each point of a line, the
// sheet's face toward the die or the holder that lies under it in plan view,
// the point's cell coordinates there and the tool's clearance.
#include <deal.II/base/geometry_info.h>

#include <formsolve/beads/bead_operator.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace formsolve
{
  namespace beads
  {
    using namespace dealii;

    namespace
    {
      /// Face coordinates (a, b) in [0, 1]^(dim-1) of plan point @p x on the
      /// face with vertices @p X (lexicographic), if it lies on it.
      template <int dim>
      bool face_coordinates(const std::array<Point<dim>, 4> &X,
                            const Point<dim>                &x,
                            double                          &a,
                            double                          &b)
      {
        const double tol = 1e-10;
        if (dim == 2)
          {
            b = 0;
            a = (x[0] - X[0][0]) / (X[1][0] - X[0][0]);
            return a >= -tol && a <= 1 + tol;
          }
        // The plan view of a bilinear face, inverted by Newton.
        a = b = 0.5;
        for (unsigned int it = 0; it < 20; ++it)
          {
            double r[2], J[2][2];
            for (unsigned int c = 0; c < 2; ++c)
              {
                r[c] = (1 - a) * (1 - b) * X[0][c] + a * (1 - b) * X[1][c] +
                       (1 - a) * b * X[2][c] + a * b * X[3][c] - x[c];
                J[c][0] =
                  (1 - b) * (X[1][c] - X[0][c]) + b * (X[3][c] - X[2][c]);
                J[c][1] =
                  (1 - a) * (X[2][c] - X[0][c]) + a * (X[3][c] - X[1][c]);
              }
            const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            if (det == 0)
              return false;
            const double da = (J[1][1] * r[0] - J[0][1] * r[1]) / det,
                         db = (J[0][0] * r[1] - J[1][0] * r[0]) / det;
            a -= da;
            b -= db;
            if (std::abs(da) + std::abs(db) < 1e-13)
              break;
          }
        return a >= -tol && a <= 1 + tol && b >= -tol && b <= 1 + tol;
      }

      /// Bilinear (linear in 2-D) weights of the face's vertices at (a, b).
      template <int dim>
      std::array<double, 4> face_weights(const double a, const double b)
      {
        if (dim == 2)
          return {{1 - a, a, 0, 0}};
        return {{(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b}};
      }

      /// z component of the face's unit normal pointing away from the cell
      /// (@p out: from the cell's centre to the face's).
      template <int dim>
      double face_side(const std::array<Point<dim>, 4> &X,
                       const Tensor<1, dim>            &out)
      {
        Tensor<1, dim> n;
        if constexpr (dim == 2)
          {
            n[0] = X[0][1] - X[1][1];
            n[1] = X[1][0] - X[0][0];
          }
        else
          n = cross_product_3d(X[1] - X[0], X[2] - X[0]);
        if (n * out < 0)
          n = -n;
        return n[dim - 1] / n.norm();
      }

      /// A line's point on a face: its index, cell and real coordinates.
      template <int dim>
      struct FacePoint
      {
        unsigned int q;
        Point<dim>   unit, x;
      };

      /// The points of @p line (indices @p order, sorted by x) that lie on
      /// face @p f with vertices @p X in plan view.
      template <int dim>
      std::vector<FacePoint<dim>>
      points_on_face(const std::vector<BeadPoint<dim>> &line,
                     const std::vector<unsigned int>   &order,
                     const std::array<Point<dim>, 4>   &X,
                     const unsigned int                 f)
      {
        const unsigned int nv    = GeometryInfo<dim>::vertices_per_face;
        double             lo[2] = {X[0][0], dim == 3 ? X[0][1] : 0.};
        double             hi[2] = {lo[0], lo[1]};
        for (unsigned int v = 1; v < nv; ++v)
          for (unsigned int c = 0; c + 1 < dim; ++c)
            {
              lo[c] = std::min(lo[c], X[v][c]);
              hi[c] = std::max(hi[c], X[v][c]);
            }
        std::vector<FacePoint<dim>> out;
        auto                        it = std::lower_bound(order.begin(),
                                   order.end(),
                                   lo[0] - 1e-9,
                                   [&](const unsigned int q, const double x) {
                                     return line[q].plan[0] < x;
                                   });
        for (; it != order.end() && line[*it].plan[0] <= hi[0] + 1e-9; ++it)
          {
            const Point<dim> &p = line[*it].plan;
            double            a, b;
            if ((dim == 3 && (p[1] < lo[1] - 1e-9 || p[1] > hi[1] + 1e-9)) ||
                !face_coordinates<dim>(X, p, a, b))
              continue;
            const auto     w = face_weights<dim>(a, b);
            FacePoint<dim> fp{*it, Point<dim>(), Point<dim>()};
            for (unsigned int v = 0; v < nv; ++v)
              {
                fp.unit +=
                  w[v] * GeometryInfo<dim>::unit_cell_vertex(
                           GeometryInfo<dim>::face_to_cell_vertices(f, v));
                fp.x += w[v] * X[v];
              }
            out.push_back(fp);
          }
        return out;
      }
    } // namespace

    template <int dim>
    void
    BeadOperator<dim>::locate(const state::State<dim>          &state,
                              const int                         side,
                              std::vector<Hit>                 &found,
                              std::vector<std::vector<double>> &clearance,
                              std::vector<std::vector<double>> &count) const
    {
      clearance.resize(lines.size());
      count.resize(lines.size());
      std::vector<std::vector<unsigned int>> order(lines.size());
      for (unsigned int b = 0; b < lines.size(); ++b)
        {
          clearance[b].assign(lines[b].size(), 0.);
          count[b].assign(lines[b].size(), 0.);
          for (unsigned int q = 0; q < lines[b].size(); ++q)
            order[b].push_back(q);
          std::sort(order[b].begin(),
                    order[b].end(),
                    [&](const unsigned int i, const unsigned int j) {
                      return lines[b][i].plan[0] < lines[b][j].plan[0];
                    });
        }
      const unsigned int t =
        side < 0 ? state.tools.die_index() : state.tools.holder_index();
      if (t == tools::ToolSet<dim>::none)
        return;
      const unsigned int nv = GeometryInfo<dim>::vertices_per_face;
      const auto        &fe = state.fe;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto vertices = state.mapping->get_vertices(cell);
          Point<dim> centre;
          for (const auto &x : vertices)
            centre += x / double(vertices.size());
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary() ||
                  cell->face(f)->boundary_id() != geometry::free_surface)
                continue;
              std::array<Point<dim>, 4> X;
              Point<dim>                mid;
              for (unsigned int v = 0; v < nv; ++v)
                {
                  X[v] =
                    vertices[GeometryInfo<dim>::face_to_cell_vertices(f, v)];
                  mid += X[v] / double(nv);
                }
              if (face_side(X, mid - centre) * side < 0.5)
                continue;
              cell->get_dof_indices(dofs);
              for (unsigned int b = 0; b < lines.size(); ++b)
                for (const auto &p : points_on_face(lines[b], order[b], X, f))
                  {
                    Tensor<1, dim> normal;
                    clearance[b][p.q] +=
                      state.tools[t].signed_distance(p.x, normal);
                    count[b][p.q] += 1;
                    Hit h{b, p.q, 0., dofs, {}};
                    for (unsigned int i = 0; i < dofs.size(); ++i)
                      {
                        const unsigned int k =
                          fe.system_to_component_index(i).first;
                        h.g.push_back(fe.shape_value_component(i, p.unit, k) *
                                      lines[b][p.q].normal[k]);
                      }
                    found.push_back(h);
                  }
            }
        }
    }

#define INSTANTIATE(dim)                                                      \
  template void BeadOperator<dim>::locate(const state::State<dim> &,          \
                                          int,                                \
                                          std::vector<Hit> &,                 \
                                          std::vector<std::vector<double>> &, \
                                          std::vector<std::vector<double>> &) \
    const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace beads
} // namespace formsolve
