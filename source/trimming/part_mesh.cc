#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/trimming/earlier_values.h>
#include <formsolve/trimming/part_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace formsolve
{
  namespace trimming
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      using FaceVertices =
        std::array<Point<dim>, GeometryInfo<dim>::vertices_per_face>;

      Point<2> nearest_on_segment(const Point<2> &p,
                                  const Point<2> &a,
                                  const Point<2> &b)
      {
        const Tensor<1, 2> ab = b - a;
        const double       l2 = ab.norm_square();
        const double s = l2 > 0 ? std::clamp((p - a) * ab / l2, 0., 1.) : 0.;
        return a + s * ab;
      }

      /// Ericson, Real-Time Collision Detection, 5.1.5.
      Point<3> nearest_on_triangle(const Point<3> &p,
                                   const Point<3> &a,
                                   const Point<3> &b,
                                   const Point<3> &c)
      {
        const Tensor<1, 3> ab = b - a, ac = c - a, ap = p - a;
        const double       d1 = ab * ap, d2 = ac * ap;
        if (d1 <= 0 && d2 <= 0)
          return a;
        const Tensor<1, 3> bp = p - b;
        const double       d3 = ab * bp, d4 = ac * bp;
        if (d3 >= 0 && d4 <= d3)
          return b;
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0)
          return a + d1 / (d1 - d3) * ab;
        const Tensor<1, 3> cp = p - c;
        const double       d5 = ab * cp, d6 = ac * cp;
        if (d6 >= 0 && d5 <= d6)
          return c;
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0)
          return a + d2 / (d2 - d6) * ac;
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
          return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
        const double denom = 1 / (va + vb + vc);
        return a + ab * (vb * denom) + ac * (vc * denom);
      }

      Point<2> nearest_on_face(const Point<2> &p, const FaceVertices<2> &f)
      {
        return nearest_on_segment(p, f[0], f[1]);
      }

      // A quadrilateral face's vertices are in lexicographic order.
      Point<3> nearest_on_face(const Point<3> &p, const FaceVertices<3> &f)
      {
        const Point<3> x = nearest_on_triangle(p, f[0], f[1], f[3]);
        const Point<3> y = nearest_on_triangle(p, f[0], f[3], f[2]);
        return p.distance(x) <= p.distance(y) ? x : y;
      }

      /// The faces between kept and cut-away cells of @p s, reference
      /// configuration, from all ranks.
      template <int dim>
      std::vector<FaceVertices<dim>> cut_surface(const state::State<dim> &s,
                                                 const KeptCells         &kept)
      {
        std::vector<double> mine;
        const auto          add = [&](const auto &face) {
          for (const unsigned int v : face->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              mine.push_back(face->vertex(v)[d]);
        };
        for (const auto &cell : s.tria.active_cell_iterators())
          {
            if (!cell->is_locally_owned() || !kept[cell->active_cell_index()])
              continue;
            for (const unsigned int f : cell->face_indices())
              {
                if (cell->at_boundary(f))
                  continue;
                if (!cell->neighbor(f)->has_children())
                  {
                    if (!kept[cell->neighbor(f)->active_cell_index()])
                      add(cell->face(f));
                    continue;
                  }
                // A finer cut-away neighbour.
                for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                  if (!kept[cell->neighbor_child_on_subface(f, c)
                              ->active_cell_index()])
                    add(cell->face(f)->child(c));
              }
          }
        std::vector<FaceVertices<dim>> faces;
        constexpr unsigned int         n = GeometryInfo<dim>::vertices_per_face;
        for (const auto &part : Utilities::MPI::all_gather(s.comm, mine))
          for (std::size_t i = 0; i + n * dim <= part.size(); i += n * dim)
            {
              FaceVertices<dim> f;
              for (unsigned int v = 0; v < n; ++v)
                for (unsigned int d = 0; d < dim; ++d)
                  f[v][d] = part[i + v * dim + d];
              faces.push_back(f);
            }
        return faces;
      }

      /// Smallest and largest corner Jacobian of a (bi-, tri-)linear cell.
      template <int dim>
      std::pair<double, double>
      corner_jacobians(const typename Triangulation<dim>::cell_iterator &c)
      {
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (const unsigned int v : c->vertex_indices())
          {
            Tensor<2, dim> J;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int w    = v ^ (1u << d);
                const double       sign = (v >> d) & 1u ? -1. : 1.;
                for (unsigned int e = 0; e < dim; ++e)
                  J[e][d] = sign * (c->vertex(w)[e] - c->vertex(v)[e]);
              }
            lo = std::min(lo, determinant(J));
            hi = std::max(hi, determinant(J));
          }
        return {lo, hi};
      }

      /// The fraction of each cell of @p serial (the earlier mesh's level
      /// @p level, every rank) that the part keeps, by volume.
      template <int dim>
      std::vector<double> kept_fractions(const state::State<dim>  &earlier,
                                         const KeptCells          &kept,
                                         const Triangulation<dim> &serial,
                                         const unsigned int        level)
      {
        // By position: the forest numbers its coarse cells its own way, so
        // cell ids of the two meshes differ; their vertices do not.
        using Key         = std::array<long long, dim>;
        const double unit = 1e-7 * earlier.prm.geometry.thickness;
        const auto   key  = [unit](const Point<dim> &c) {
          Key k;
          for (unsigned int d = 0; d < dim; ++d)
            k[d] = std::llround(c[d] / unit);
          return k;
        };
        std::map<Key, unsigned int> index;
        for (const auto &cell : serial.active_cell_iterators())
          index[key(cell->center())] = cell->active_cell_index();
        std::vector<double> in(serial.n_active_cells()),
          all(serial.n_active_cells());
        for (const auto &cell : earlier.tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              typename Triangulation<dim>::cell_iterator a = cell;
              while (a->level() > static_cast<int>(level))
                a = a->parent();
              const auto i = index.find(key(a->center()));
              AssertThrow(i != index.end(), ExcInternalError());
              const double v = cell->measure();
              all[i->second] += v;
              if (kept[cell->active_cell_index()])
                in[i->second] += v;
            }
        Utilities::MPI::sum(in, earlier.comm, in);
        Utilities::MPI::sum(all, earlier.comm, all);
        for (std::size_t i = 0; i < in.size(); ++i)
          in[i] = all[i] > 0 ? in[i] / all[i] : 0;
        return in;
      }

      /// The vertices of @p serial's cells that stay (@p in) on its side
      /// faces (not the sheet's surfaces) that lie in a cut-away cell of
      /// @p earlier: the rim of a cell the cut crosses. Located by rank 0
      /// (a little inside the cell, where the search is quick), then sent
      /// to all.
      template <int dim>
      std::vector<bool> outside(const state::State<dim>  &earlier,
                                const KeptCells          &kept,
                                const Triangulation<dim> &serial,
                                const std::vector<bool>  &in)
      {
        const double              t = earlier.prm.geometry.thickness;
        std::vector<Point<dim>>   points;
        std::vector<unsigned int> index;
        const bool root = Utilities::MPI::this_mpi_process(earlier.comm) == 0;
        for (const auto &cell : serial.active_cell_iterators())
          if (root && in[cell->active_cell_index()])
            for (const unsigned int f : cell->face_indices())
              {
                const auto   face = cell->face(f);
                const double z    = face->center()[dim - 1];
                if (!face->at_boundary() || std::abs(z) < 1e-6 * t ||
                    std::abs(z - t) < 1e-6 * t)
                  continue;
                for (const unsigned int v : face->vertex_indices())
                  {
                    points.push_back(face->vertex(v) +
                                     1e-4 * (cell->center() - face->vertex(v)));
                    index.push_back(face->vertex_index(v));
                  }
              }
        Utilities::MPI::RemotePointEvaluation<dim> cache(1e-6, true);
        locate(earlier, points, cache, nullptr);
        const auto cut_away =
          cell_values(earlier, cache, [&](const auto &cell, const auto &) {
            return kept[cell->active_cell_index()] ? 0. : 1.;
          });
        std::vector<char> flags(serial.n_vertices(), 0);
        for (std::size_t p = 0; p < cut_away.size(); ++p)
          if (cut_away[p] > 0.5) // NaN (not found): not beyond
            flags[index[p]] = 1;
        flags = Utilities::MPI::broadcast(earlier.comm, flags, 0);
        return std::vector<bool>(flags.begin(), flags.end());
      }

      /// Moves the nodes of @p serial between cells that stay (@p in) and
      /// cells left out, and those of cells that stay on the rim beyond the
      /// cut, onto the cut of @p earlier (eq. 14e); fills @p r's moves.
      template <int dim>
      void move_edge(const state::State<dim> &earlier,
                     const KeptCells         &kept,
                     Triangulation<dim>      &serial,
                     const std::vector<bool> &in,
                     const std::vector<bool> &touches_in,
                     const std::vector<bool> &touches_out,
                     PartMesh                &r)
      {
        const auto &g = earlier.prm.geometry;
        // Each column of edge nodes (through the thickness) moves together
        // in plan, to the mean of its nodes' nearest points on the cut, so
        // that the layers stay planar and the columns upright.
        const auto surface = cut_surface(earlier, kept);
        // Nodes of cells that stay on the blank's rim beyond the cut move too.
        const auto   beyond = outside(earlier, kept, serial, in);
        const double tol    = 1e-6 * g.thickness;
        using Key           = std::array<long long, dim - 1>;
        std::map<Key, std::pair<Tensor<1, dim>, unsigned int>> columns;
        const auto key = [&](const Point<dim> &p) {
          Key k;
          for (unsigned int d = 0; d + 1 < dim; ++d)
            k[d] = std::llround(p[d] / tol);
          return k;
        };
        std::vector<bool> done(serial.n_vertices());
        for (const auto &cell : serial.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int i = cell->vertex_index(v);
              if (done[i] ||
                  !(touches_in[i] && (touches_out[i] || beyond[i])) ||
                  surface.empty())
                continue;
              done[i]            = true;
              const Point<dim> p = cell->vertex(v);
              Point<dim>       best;
              double           d = std::numeric_limits<double>::max();
              for (const auto &f : surface)
                {
                  const Point<dim> x = nearest_on_face(p, f);
                  if (p.distance(x) < d)
                    d = p.distance(x), best = x;
                }
              auto &c = columns[key(p)];
              c.first += best - p;
              ++c.second;
            }
        std::fill(done.begin(), done.end(), false);
        std::set<typename Triangulation<dim>::active_cell_iterator> moved;
        for (const auto &cell : serial.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int i = cell->vertex_index(v);
              const auto         c = columns.find(key(cell->vertex(v)));
              if (!touches_in[i] || c == columns.end())
                continue;
              moved.insert(cell);
              if (done[i])
                continue;
              done[i] = true;
              Tensor<1, dim> shift;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                {
                  const bool on_plane =
                    std::abs(cell->vertex(v)[d]) < tol &&
                    ((d == 0 && model::symmetric_in_x(g.model)) ||
                     (d == 1 && model::symmetric_in_y(g.model)) ||
                     (d == 0 && g.model == model::Model::axisymmetric));
                  if (!on_plane)
                    shift[d] = c->second.first[d] / c->second.second;
                }
              r.largest_move = std::max(r.largest_move, shift.norm());
              cell->vertex(v) += shift;
            }
        for (const auto &cell : moved)
          if (in[cell->active_cell_index()])
            {
              const auto [lo, hi] = corner_jacobians<dim>(cell);
              AssertThrow(lo > 0,
                          ExcMessage(
                            "Geometry/Start from: moving the earlier mesh's "
                            "nodes onto the trimmed edge turns a cell at " +
                            Utilities::to_string(cell->center()[0]) + ", " +
                            Utilities::to_string(cell->center()[1]) +
                            " mm inside out; trim along a smoother line or "
                            "refine the earlier run's mesh (Mesh/Planform "
                            "refinements)"));
              r.worst_corner_ratio = std::min(r.worst_corner_ratio, lo / hi);
            }
      }
    } // namespace

    template <int dim>
    PartMesh create_part_mesh(const state::State<dim> &earlier,
                              const KeptCells         &kept,
                              parallel::distributed::Triangulation<dim> &tria)
    {
      const auto &g = earlier.prm.geometry;
      PartMesh    r;
      int         level = std::numeric_limits<int>::max();
      for (const auto &cell : earlier.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          level = std::min(level, cell->level());
      r.level = Utilities::MPI::min(level, earlier.comm);

      Triangulation<dim> serial;
      geometry::create_coarse_blank_mesh(g, earlier.prm.mesh, serial);
      serial.refine_global(r.level);
      const auto fraction = kept_fractions(earlier, kept, serial, r.level);

      // A cell stays if the part keeps most of it; nodes between cells that
      // stay and cells left out are the part's new edge.
      std::vector<bool> touches_in(serial.n_vertices()),
        touches_out(serial.n_vertices()), in(serial.n_active_cells());
      std::set<typename Triangulation<dim>::active_cell_iterator> left_out;
      for (const auto &cell : serial.active_cell_iterators())
        {
          const bool i = fraction[cell->active_cell_index()] >= 0.5;
          in[cell->active_cell_index()] = i;
          for (const unsigned int v : cell->vertex_indices())
            (i ? touches_in : touches_out)[cell->vertex_index(v)] = true;
          if (!i)
            left_out.insert(cell);
        }
      r.left_out = left_out.size();
      r.kept     = serial.n_active_cells() - r.left_out;
      AssertThrow(r.kept > 0,
                  ExcMessage("Geometry/Start from: the trimmed part is "
                             "smaller than any cell of the earlier run's "
                             "coarsest mesh level; nothing to form"));

      move_edge(earlier, kept, serial, in, touches_in, touches_out, r);

      Triangulation<dim> part;
      GridGenerator::create_triangulation_with_removed_cells(serial,
                                                             left_out,
                                                             part);
      geometry::set_boundary_ids(g, part);
      tria.copy_triangulation(part);
      return r;
    }

#define INSTANTIATE(dim)              \
  template PartMesh create_part_mesh( \
    const state::State<dim> &,        \
    const KeptCells &,                \
    parallel::distributed::Triangulation<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace trimming
} // namespace formsolve
