#include <deal.II/base/mpi.h>

#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/column_owner.h>
#include <formsolve/postprocess/through_thickness.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /// Planform bits of a child index (lexicographic: x, then y, then the
      /// layer axis), and their number.
      constexpr unsigned int planform_bits(const int dim)
      {
        return dim - 1;
      }

      /// One cell: coarse planform key, level, planform path, reference
      /// height, volume averages of I and W, current centre.
      template <int dim>
      constexpr unsigned int record_size()
      {
        return (dim - 1) + 2 + 3 + dim;
      }

      /// A footprint in the planform tree of a coarse planform cell.
      struct Node
      {
        unsigned int       level;
        unsigned long long path;
        bool               operator<(const Node &o) const
        {
          return level < o.level || (level == o.level && path < o.path);
        }
        Node parent(const unsigned int bits) const
        {
          return {level - 1, path >> bits};
        }
      };

      /// A larger value, or a tie within round-off (mirror columns of a
      /// symmetric part) at a larger x: the same choice on any number of
      /// ranks.
      template <int dim>
      void
      take_larger(ColumnMaximum<dim> &m, const double v, const Point<dim> &x)
      {
        const double tie = 1e-9 * std::abs(m.value);
        if (v > m.value + tie ||
            (v > 0 && v >= m.value - tie && x[0] > m.location[0]))
          m = {v, x};
      }

      template <int dim>
      struct Stack
      {
        double     oyane = 0, work = 0, height = 0; // sums times h, sum h
        Point<dim> centre;                          // sum of centres times h
      };

      /// This rank's cell records.
      template <int dim>
      std::vector<double> local_records(const state::State<dim> &state)
      {
        constexpr double           quantum = 1e-7; // mm, as SheetMeasures::key
        const unsigned int         bits    = planform_bits(dim);
        const unsigned int         nc      = 1u << bits; // footprint corners
        model::CellKinematics<dim> k(state.kinematics,
                                     *state.mapping,
                                     state.fe,
                                     state.history_rule,
                                     update_default,
                                     &state.reference_mapping);
        std::vector<double>        out;
        for (const auto &cell : state.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              // The path from the coarse cell, planform bits of each level.
              unsigned long long                         path = 0, shift = 0;
              typename Triangulation<dim>::cell_iterator c = cell;
              while (c->level() > 0)
                {
                  const auto   parent = c->parent();
                  unsigned int i      = 0;
                  while (parent->child(i) != c)
                    ++i;
                  path |= static_cast<unsigned long long>(i & (nc - 1))
                          << shift;
                  shift += bits;
                  c = parent;
                }
              Point<dim> centre;
              for (unsigned int v = 0; v < nc; ++v)
                centre += c->vertex(v) / double(nc);
              for (unsigned int d = 0; d + 1 < dim; ++d)
                out.push_back(std::llround(centre[d] / quantum));
              out.push_back(cell->level());
              out.push_back(static_cast<double>(path));
              out.push_back(cell->vertex(nc)[dim - 1] -
                            cell->vertex(0)[dim - 1]);
              k.reinit(cell);
              double     volume = 0, oyane = 0, work = 0;
              const auto h = state.history.get_data(cell);
              for (unsigned int q = 0; q < h.size(); ++q)
                {
                  const double dV = k.dV_reference(q);
                  volume += dV;
                  oyane += h[q]->oyane * dV;
                  work += h[q]->cockcroft_latham * dV;
                }
              out.push_back(oyane / volume);
              out.push_back(work / volume);
              Point<dim> unit_centre;
              for (unsigned int d = 0; d < dim; ++d)
                unit_centre[d] = 0.5;
              const Point<dim> x =
                state.mapping->transform_unit_to_real_cell(cell, unit_centre);
              for (unsigned int d = 0; d < dim; ++d)
                out.push_back(x[d]);
            }
        return out;
      }

      template <int dim>
      Node node_of(const double *r)
      {
        return Node{static_cast<unsigned int>(r[dim - 1]),
                    static_cast<unsigned long long>(r[dim])};
      }

      /// The sums per footprint of every coarse planform cell, in an
      /// order that does not depend on the partition (the same result on any
      /// number of ranks).
      template <int dim>
      std::map<std::vector<double>, std::map<Node, Stack<dim>>>
      footprint_sums(const std::vector<std::vector<double>> &all)
      {
        constexpr unsigned int      R = record_size<dim>();
        std::vector<const double *> sorted;
        for (const auto &v : all)
          for (std::size_t i = 0; i < v.size(); i += R)
            sorted.push_back(&v[i]);
        std::sort(sorted.begin(),
                  sorted.end(),
                  [](const double *a, const double *b) {
                    return std::lexicographical_compare(a, a + R, b, b + R);
                  });
        std::map<std::vector<double>, std::map<Node, Stack<dim>>> trees;
        for (const double *r : sorted)
          {
            auto &s =
              trees[std::vector<double>(r, r + dim - 1)][node_of<dim>(r)];
            const double h = r[dim + 1];
            s.oyane += r[dim + 2] * h;
            s.work += r[dim + 3] * h;
            s.height += h;
            for (unsigned int d = 0; d < dim; ++d)
              s.centre[d] += r[dim + 4 + d] * h;
          }
        return trees;
      }

      /// The maxima over the leaf columns (eq. 12a) and, in
      /// @p through, the largest deciding column average through each
      /// footprint.
      template <int dim>
      ColumnDamage<dim> column_maxima(
        const std::map<std::vector<double>, std::map<Node, Stack<dim>>> &trees,
        const material::DamageCriteria                                  &damage,
        const double                                                     t0,
        std::map<std::vector<double>, std::map<Node, double>> &through)
      {
        const unsigned int bits = planform_bits(dim);
        const bool         deciding_cl =
          damage.criterion() == parameters::FractureCriterion::cockcroft_latham;
        ColumnDamage<dim> result;
        for (const auto &[key, tree] : trees)
          {
            std::map<Node, bool> inner;
            for (const auto &[n, s] : tree)
              for (Node a = n; a.level > 0;)
                {
                  a        = a.parent(bits);
                  inner[a] = true;
                }
            for (const auto &[leaf, s] : tree)
              {
                if (inner.count(leaf))
                  continue;
                Stack<dim> column = s;
                for (Node a = leaf; a.level > 0;)
                  {
                    a = a.parent(bits);
                    if (const auto p = tree.find(a); p != tree.end())
                      {
                        column.oyane += p->second.oyane;
                        column.work += p->second.work;
                        column.height += p->second.height;
                        column.centre += p->second.centre;
                      }
                  }
                result.height_error =
                  std::max(result.height_error,
                           std::abs(column.height / t0 - 1));
                const double oyane = column.oyane / column.height;
                const double cl =
                  damage.cockcroft_latham(column.work / column.height);
                const Point<dim> x = column.centre / column.height;
                take_larger(result.oyane, oyane, x);
                take_larger(result.cockcroft_latham, cl, x);
                const double decide = deciding_cl ? cl : oyane;
                for (Node a = leaf;; a = a.parent(bits))
                  {
                    double &m = through[key][a];
                    m         = std::max(m, decide);
                    if (a.level == 0)
                      break;
                  }
              }
          }
        return result;
      }
    } // namespace

    namespace
    {
      /// The largest column averages of all ranks and the largest height
      /// error (collective; the same on every rank).
      template <int dim>
      ColumnDamage<dim> combined(const MPI_Comm           comm,
                                 const ColumnDamage<dim> &mine)
      {
        std::vector<double> packed{mine.height_error,
                                   mine.oyane.value,
                                   mine.cockcroft_latham.value};
        for (unsigned int d = 0; d < dim; ++d)
          packed.push_back(mine.oyane.location[d]);
        for (unsigned int d = 0; d < dim; ++d)
          packed.push_back(mine.cockcroft_latham.location[d]);
        ColumnDamage<dim> result;
        for (const auto &v : Utilities::MPI::all_gather(comm, packed))
          {
            Point<dim> x, y;
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = v[3 + d], y[d] = v[3 + dim + d];
            result.height_error = std::max(result.height_error, v[0]);
            take_larger(result.oyane, v[1], x);
            take_larger(result.cockcroft_latham, v[2], y);
          }
        return result;
      }
    } // namespace

    template <int dim>
    ColumnDamage<dim>
    ThroughThicknessDamage<dim>::measure(const state::State<dim>        &state,
                                         const material::DamageCriteria &damage,
                                         const bool cell_values)
    {
      constexpr unsigned int R   = record_size<dim>();
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(state.comm);
      // Each cell's record goes to the rank that owns its coarse planform
      // cell's column, where the whole column meets.
      const std::vector<double> mine = local_records(state);
      std::vector<unsigned int> owner(mine.size() / R);
      Outbox                    out;
      for (std::size_t r = 0; r < owner.size(); ++r)
        {
          std::array<long long, dim - 1> key;
          for (unsigned int d = 0; d + 1 < dim; ++d)
            key[d] = static_cast<long long>(mine[R * r + d]);
          owner[r] = column_owner(key, n_ranks);
          out[owner[r]].insert(out[owner[r]].end(),
                               mine.begin() + R * r,
                               mine.begin() + R * (r + 1));
        }
      const Outbox received = exchange_records(state.comm, out);
      std::vector<std::vector<double>> all;
      for (const auto &[rank, v] : received)
        all.push_back(v);
      std::map<std::vector<double>, std::map<Node, double>> through;
      const ColumnDamage<dim>                               result =
        combined(state.comm,
                 column_maxima<dim>(footprint_sums<dim>(all),
                                    damage,
                                    state.prm.geometry.thickness,
                                    through));
      if (cell_values)
        {
          // The owners answer each record with its footprint's value.
          Outbox answers;
          for (const auto &[rank, v] : received)
            for (std::size_t i = 0; i < v.size(); i += R)
              answers[rank].push_back(
                through[std::vector<double>(&v[i], &v[i] + dim - 1)]
                       [node_of<dim>(&v[i])]);
          const Outbox values = exchange_records(state.comm, answers);
          std::map<unsigned int, std::size_t> next;
          std::size_t                         r = 0;
          cells.reinit(state.tria.n_active_cells());
          for (const auto &cell : state.dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const unsigned int o             = owner[r++];
                cells[cell->active_cell_index()] = values.at(o)[next[o]++];
              }
        }
      return result;
    }

#define INSTANTIATE(dim) template class ThroughThicknessDamage<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
