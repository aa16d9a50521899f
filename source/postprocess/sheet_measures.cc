#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/sheet_measures.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    template <int dim>
    SheetMeasures<dim>::SheetMeasures(const parameters::Run &prm)
        : t0(prm.geometry.thickness)
        , diagonal(prm.geometry.blank_shape == parameters::BlankShape::rectangle
                     ? std::atan2(prm.geometry.blank_width,
                                  prm.geometry.blank_length) *
                         180 / M_PI
                     : 45.)
        , flc(prm.material, prm.geometry.thickness)
    {}

    template <int dim>
    typename SheetMeasures<dim>::Key
    SheetMeasures<dim>::key(const Point<dim> &x)
    {
      Key k;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        k[d] = std::llround(x[d] / quantum);
      return k;
    }

    template <int dim>
    double SheetMeasures<dim>::distance(const Key &a, const Key &b)
    {
      double d2 = 0;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        d2 += std::pow(double(a[d] - b[d]) * quantum, 2);
      return std::sqrt(d2);
    }

    template <int dim>
    void SheetMeasures<dim>::measure(const state::State<dim>        &state,
                                     const material::DamageCriteria &damage)
    {
      const std::pair<unsigned int, types::global_dof_index> now{
        state.step,
        state.dof_handler.n_dofs()};
      if (now == measured)
        return;
      std::vector<std::array<Key, n_corners>> mid;
      const Outbox                            received =
        exchange_records(state.comm, local_records(state, damage, mid));
      std::map<unsigned int, std::vector<Key>> corners;
      assemble_columns(received, corners);
      cell_centre_thickness(state.comm, mid, corners);
      sum      = summarise(state.comm);
      measured = now;
    }

    template <int dim>
    std::size_t SheetMeasures<dim>::find(const Key &k) const
    {
      const auto it = std::lower_bound(keys.begin(), keys.end(), k);
      return it != keys.end() && *it == k ? std::size_t(it - keys.begin())
                                          : cols.size();
    }

    template <int dim>
    void SheetMeasures<dim>::node_records(const state::State<dim> &state,
                                          Outbox                  &out) const
    {
      // Surface nodes (top, bottom) and rim nodes between them, and
      // whether a tool presses on each.
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(state.comm);
      const double       tol     = 1e-6 * t0;
      std::vector<bool>  touching(state.contact_set.nodes.size(), false);
      for (const auto &pair : state.contact_set.pairs)
        if (pair.active)
          touching[pair.node] = true;
      for (unsigned int n = 0; n < state.contact_set.nodes.size(); ++n)
        {
          const auto       &node  = state.contact_set.nodes[n];
          const Point<dim> &X     = node.reference_position;
          const double      z     = X[dim - 1];
          const double      side  = z < tol ? 0. : z > t0 - tol ? 1. : 2.;
          const Key         k     = key(X);
          auto             &nodes = out[column_owner(k, n_ranks)];
          nodes.push_back(node_record);
          nodes.insert(nodes.end(), k.begin(), k.end());
          nodes.push_back(side);
          nodes.push_back(touching[n] ? 1. : 0.);
          for (unsigned int d = 0; d < dim; ++d)
            nodes.push_back(X[d] + state.displacement_ghost[node.dofs[d]]);
        }
    }

    template <int dim>
    Outbox SheetMeasures<dim>::local_records(
      const state::State<dim>                 &state,
      const material::DamageCriteria          &damage,
      std::vector<std::array<Key, n_corners>> &mid) const
    {
      constexpr unsigned int nc  = n_corners;
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(state.comm);
      const double       tol     = 1e-6 * t0;
      Outbox             out;
      node_records(state, out);

      // Cells: mid-plane strain and normal, and damage per planform cell.
      const double zm = 0.5 * t0;
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto   x  = state.mapping->get_vertices(cell);
          const double zb = cell->vertex(0)[dim - 1];
          const double zt = cell->vertex(nc)[dim - 1];
          Assert(zt > zb,
                 ExcInternalError()); // layers along the local last axis
          double dmax = 0;
          for (const auto &h : state.history.get_data(cell))
            dmax =
              std::max(dmax, damage.deciding(h->oyane, h->cockcroft_latham));
          std::array<Key, n_corners> corner;
          for (unsigned int c = 0; c < nc; ++c)
            {
              corner[c]  = key(cell->vertex(c));
              auto &recs = out[column_owner(corner[c], n_ranks)];
              recs.push_back(damage_record);
              recs.insert(recs.end(), corner[c].begin(), corner[c].end());
              recs.push_back(dmax);
            }
          if (!(zb <= zm + tol && zm + tol < zt))
            continue;
          const double                      zeta = (zm - zb) / (zt - zb);
          std::array<Point<dim>, n_corners> m;
          for (unsigned int c = 0; c < nc; ++c)
            m[c] = x[c] + zeta * (x[c + nc] - x[c]);
          double         major, minor;
          Tensor<1, dim> normal;
          if constexpr (dim == 2)
            {
              // Stretch along the section; across it r/R (hoop) in
              // axisymmetry, 1 in plane strain.
              const double R0 = cell->vertex(0)[0], R1 = cell->vertex(1)[0];
              const Tensor<1, 2> t  = m[1] - m[0];
              const double       ls = t.norm() / std::abs(R1 - R0);
              const double       lh =
                state.kinematics.axisymmetric()
                        ? 0.5 * (m[0][0] + m[1][0]) / (0.5 * (R0 + R1))
                        : 1.;
              major     = std::log(std::max(ls, lh));
              minor     = std::log(std::min(ls, lh));
              normal[0] = -t[1] / t.norm();
              normal[1] = t[0] / t.norm();
            }
          else
            {
              // Surface deformation gradient F = G J^-1 at the quad centre.
              Tensor<1, 3> g1 = 0.5 * ((m[1] - m[0]) + (m[3] - m[2]));
              Tensor<1, 3> g2 = 0.5 * ((m[2] - m[0]) + (m[3] - m[1]));
              auto X = [&](const unsigned int v) { return cell->vertex(v); };
              const double J11 = 0.5 * ((X(1) - X(0))[0] + (X(3) - X(2))[0]);
              const double J21 = 0.5 * ((X(1) - X(0))[1] + (X(3) - X(2))[1]);
              const double J12 = 0.5 * ((X(2) - X(0))[0] + (X(3) - X(1))[0]);
              const double J22 = 0.5 * ((X(2) - X(0))[1] + (X(3) - X(1))[1]);
              const double det = J11 * J22 - J12 * J21;
              const Tensor<1, 3> f1  = (J22 * g1 - J21 * g2) / det;
              const Tensor<1, 3> f2  = (-J12 * g1 + J11 * g2) / det;
              const double       c11 = f1 * f1, c22 = f2 * f2, c12 = f1 * f2;
              const double       mean = 0.5 * (c11 + c22);
              const double       dev =
                std::sqrt(0.25 * (c11 - c22) * (c11 - c22) + c12 * c12);
              major  = 0.5 * std::log(mean + dev);
              minor  = 0.5 * std::log(mean - dev);
              normal = cross_product_3d(g1, g2);
              normal /= normal.norm();
            }
          mid.push_back(corner);
          for (unsigned int c = 0; c < nc; ++c)
            {
              auto &recs = out[column_owner(corner[c], n_ranks)];
              recs.push_back(corner_record);
              recs.insert(recs.end(), corner[c].begin(), corner[c].end());
              for (unsigned int d = 0; d < dim; ++d)
                recs.push_back(m[c][d]);
              recs.push_back(major);
              recs.push_back(minor);
              for (unsigned int d = 0; d < dim; ++d)
                recs.push_back(normal[d]);
            }
        }
      return out;
    }

    template <int dim>
    std::vector<NodalScalar>
    SheetMeasures<dim>::nodal_fields(const state::State<dim> &state)
    {
      // Each rank asks the owners of its DoFs' columns for thickness,
      // thinning, major, minor and zone (NaN: no column there).
      constexpr unsigned int nk = dim - 1, nf = 5;
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(state.comm);
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                           state.dof_handler,
                                           support);
      const auto                            &fe = state.dof_handler.get_fe();
      std::vector<types::global_dof_index>   dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, Key> asked;
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int j = 0; j < dofs.size(); ++j)
              if (fe.system_to_component_index(j).first == 0 &&
                  state.owned.is_element(dofs[j]))
                asked[dofs[j]] = key(support[dofs[j]]);
          }
      Outbox questions;
      for (const auto &[dof, k] : asked)
        {
          auto &q = questions[column_owner(k, n_ranks)];
          q.insert(q.end(), k.begin(), k.end());
        }
      Outbox answers;
      for (const auto &[rank, q] : exchange_records(state.comm, questions))
        for (std::size_t i = 0; i < q.size(); i += nk)
          {
            Key k;
            for (unsigned int d = 0; d < nk; ++d)
              k[d] = static_cast<long long>(q[i + d]);
            const std::size_t c = find(k);
            auto             &a = answers[rank];
            if (c == cols.size())
              a.insert(a.end(), nf, std::numeric_limits<double>::quiet_NaN());
            else
              a.insert(a.end(),
                       {cols[c].thickness,
                        100. * (1. - cols[c].thickness / t0),
                        cols[c].major,
                        cols[c].minor,
                        double(static_cast<int>(cols[c].zone))});
          }
      const Outbox              values = exchange_records(state.comm, answers);
      std::array<VectorType, 5> owned;
      for (auto &v : owned)
        v.reinit(state.owned, state.comm);
      std::map<unsigned int, std::size_t> next;
      for (const auto &[dof, k] : asked)
        {
          const unsigned int o = column_owner(k, n_ranks);
          const double      *v = &values.at(o)[nf * next[o]++];
          if (!std::isnan(v[0]))
            for (unsigned int f = 0; f < nf; ++f)
              owned[f][dof] = v[f];
        }
      for (unsigned int f = 0; f < nf; ++f)
        {
          owned[f].compress(VectorOperation::insert);
          fields[f].reinit(state.owned, state.relevant, state.comm);
          fields[f] = owned[f];
        }
      return {{"thickness", &fields[0], 0},
              {"thinning_percent", &fields[1], 0},
              {"major_strain", &fields[2], 0},
              {"minor_strain", &fields[3], 0},
              {"safety_zone", &fields[4], 0}};
    }

    namespace
    {
      /// Numbers per column in gathered_columns(): key, then the column.
      template <int dim>
      constexpr unsigned int packed_size = dim - 1 + 2 + dim + 9;

      template <int dim>
      void pack(const std::array<long long, dim - 1> &k,
                const SheetColumn<dim>               &c,
                std::vector<double>                  &out)
      {
        out.insert(out.end(), k.begin(), k.end());
        out.push_back(c.reference_radius);
        out.push_back(c.reference_angle);
        for (unsigned int d = 0; d < dim; ++d)
          out.push_back(c.mid[d]);
        out.insert(out.end(),
                   {c.thickness,
                    c.major,
                    c.minor,
                    c.damage,
                    double(static_cast<int>(c.zone)),
                    double(c.rim),
                    double(c.squeezed),
                    c.top,
                    c.bottom});
      }

      template <int dim>
      SheetColumn<dim> unpack(const double *v)
      {
        SheetColumn<dim> c;
        v += dim - 1;
        c.reference_radius = *v++;
        c.reference_angle  = *v++;
        for (unsigned int d = 0; d < dim; ++d)
          c.mid[d] = *v++;
        c.thickness = *v++;
        c.major     = *v++;
        c.minor     = *v++;
        c.damage    = *v++;
        c.zone      = material::SafetyZone(static_cast<int>(*v++));
        c.rim       = *v++ != 0.;
        c.squeezed  = *v++ != 0.;
        c.top       = *v++;
        c.bottom    = *v++;
        return c;
      }
    } // namespace

    template <int dim>
    std::vector<SheetColumn<dim>>
    SheetMeasures<dim>::gathered_columns(const MPI_Comm comm) const
    {
      constexpr unsigned int size = packed_size<dim>;
      std::vector<double>    mine;
      for (std::size_t c = 0; c < cols.size(); ++c)
        pack(keys[c], cols[c], mine);
      std::map<Key, SheetColumn<dim>> all; // in the order of the keys
      for (const auto &v : Utilities::MPI::gather(comm, mine, 0))
        for (std::size_t i = 0; i < v.size(); i += size)
          {
            Key k;
            for (unsigned int d = 0; d + 1 < dim; ++d)
              k[d] = static_cast<long long>(v[i + d]);
            all[k] = unpack<dim>(&v[i]);
          }
      std::vector<SheetColumn<dim>> out;
      for (const auto &[k, c] : all)
        out.push_back(c);
      return out;
    }

    template <int dim>
    void SheetMeasures<dim>::write_csv(const MPI_Comm     comm,
                                       const std::string &directory,
                                       const std::string &name) const
    {
      const auto all = gathered_columns(comm);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::ostringstream f;
      f << "reference_radius,reference_angle,r,z,thickness,thinning_percent,"
           "major_strain,minor_strain,damage,zone,zone_name,rim\n";
      f.precision(8);
      for (const auto &c : all)
        f << c.reference_radius << ',' << c.reference_angle << ','
          << (dim == 2 ? c.mid[0] : std::hypot(c.mid[0], c.mid[1])) << ','
          << c.mid[dim - 1] << ',' << c.thickness << ','
          << 100. * (1. - c.thickness / t0) << ',' << c.major << ',' << c.minor
          << ',' << c.damage << ',' << static_cast<int>(c.zone) << ','
          << material::zone_name(c.zone) << ',' << c.rim << '\n';
      std::ostringstream g;
      g << "# " << flc.source() << "\nminor_strain,major_strain\n";
      for (int i = -60; i <= 60; ++i)
        g << 0.01 * i << ',' << flc.major(0.01 * i) << '\n';
      write_atomically(directory + "/" + name,
                       [&](std::ostream &o) { o << f.str(); });
      write_atomically(directory + "/flc.csv",
                       [&](std::ostream &o) { o << g.str(); });
    }

#define INSTANTIATE(dim) template class SheetMeasures<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
