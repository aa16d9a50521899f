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
      const Records local  = local_records(state, damage);
      const auto all_nodes = Utilities::MPI::gather(state.comm, local.nodes, 0);
      const auto all_cells = Utilities::MPI::gather(state.comm, local.cells, 0);
      const auto all_damages =
        Utilities::MPI::gather(state.comm, local.damages, 0);

      std::vector<double> packed; // the summary, broadcast from rank 0
      cols.clear();
      keys.clear();
      if (Utilities::MPI::this_mpi_process(state.comm) == 0)
        {
          assemble_columns(all_nodes, all_cells, all_damages);
          const SheetSummary<dim> s = summarise();
          packed                    = {s.min_thickness,
                                       s.min_thickness_radius,
                                       s.max_thinning,
                                       s.max_thickening,
                                       s.flc_margin,
                                       s.cup_height,
                                       s.blank_radius,
                                       s.flc_radius,
                                       s.flc_angle};
          for (unsigned int d = 0; d < dim; ++d)
            packed.push_back(s.min_thickness_location[d]);
          for (unsigned int d = 0; d < dim; ++d)
            packed.push_back(s.flc_location[d]);
          for (const auto n : s.zone_count)
            packed.push_back(n);
          packed.insert(packed.end(), s.rim_radius.begin(), s.rim_radius.end());
          packed.insert(packed.end(), s.draw_in.begin(), s.draw_in.end());
        }
      packed            = Utilities::MPI::broadcast(state.comm, packed, 0);
      std::size_t i     = 0;
      sum.min_thickness = packed[i++];
      sum.min_thickness_radius = packed[i++];
      sum.max_thinning         = packed[i++];
      sum.max_thickening       = packed[i++];
      sum.flc_margin           = packed[i++];
      sum.cup_height           = packed[i++];
      sum.blank_radius         = packed[i++];
      sum.flc_radius           = packed[i++];
      sum.flc_angle            = packed[i++];
      for (unsigned int d = 0; d < dim; ++d)
        sum.min_thickness_location[d] = packed[i++];
      for (unsigned int d = 0; d < dim; ++d)
        sum.flc_location[d] = packed[i++];
      for (auto &n : sum.zone_count)
        n = static_cast<unsigned int>(packed[i++]);
      const std::size_t directions = (packed.size() - i) / 2;
      sum.rim_radius.assign(packed.begin() + i,
                            packed.begin() + i + directions);
      sum.draw_in.assign(packed.begin() + i + directions, packed.end());
    }

    template <int dim>
    std::vector<double>
    SheetMeasures<dim>::node_records(const state::State<dim> &state) const
    {
      // Surface nodes (top, bottom) and rim nodes between them, and
      // whether a tool presses on each.
      const double        tol = 1e-6 * t0;
      std::vector<double> nodes;
      std::vector<bool>   touching(state.contact_set.nodes.size(), false);
      for (const auto &pair : state.contact_set.pairs)
        if (pair.active)
          touching[pair.node] = true;
      for (unsigned int n = 0; n < state.contact_set.nodes.size(); ++n)
        {
          const auto       &node = state.contact_set.nodes[n];
          const Point<dim> &X    = node.reference_position;
          const double      z    = X[dim - 1];
          const double      side = z < tol ? 0. : z > t0 - tol ? 1. : 2.;
          for (const auto k : key(X))
            nodes.push_back(k);
          nodes.push_back(side);
          nodes.push_back(touching[n] ? 1. : 0.);
          for (unsigned int d = 0; d < dim; ++d)
            nodes.push_back(X[d] + state.displacement_ghost[node.dofs[d]]);
        }
      return nodes;
    }

    template <int dim>
    typename SheetMeasures<dim>::Records SheetMeasures<dim>::local_records(
      const state::State<dim>        &state,
      const material::DamageCriteria &damage) const
    {
      constexpr unsigned int nc  = n_corners;
      const double           tol = 1e-6 * t0;
      Records                r;
      r.nodes                    = node_records(state);
      std::vector<double> &cells = r.cells, &damages = r.damages;

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
          for (unsigned int c = 0; c < nc; ++c)
            for (const auto k : key(cell->vertex(c)))
              damages.push_back(k);
          damages.push_back(dmax);
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
              // Meridional stretch along the section, hoop stretch r/R.
              const double R0 = cell->vertex(0)[0], R1 = cell->vertex(1)[0];
              const Tensor<1, 2> t  = m[1] - m[0];
              const double       ls = t.norm() / std::abs(R1 - R0);
              const double lh = 0.5 * (m[0][0] + m[1][0]) / (0.5 * (R0 + R1));
              major           = std::log(std::max(ls, lh));
              minor           = std::log(std::min(ls, lh));
              normal[0]       = -t[1] / t.norm();
              normal[1]       = t[0] / t.norm();
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
          for (unsigned int c = 0; c < nc; ++c)
            {
              for (const auto k : key(cell->vertex(c)))
                cells.push_back(k);
              for (unsigned int d = 0; d < dim; ++d)
                cells.push_back(m[c][d]);
            }
          cells.push_back(major);
          cells.push_back(minor);
          for (unsigned int d = 0; d < dim; ++d)
            cells.push_back(normal[d]);
        }

      return r;
    }

    template <int dim>
    std::vector<NodalScalar>
    SheetMeasures<dim>::nodal_fields(const state::State<dim> &state)
    {
      // Columns from rank 0: key, thickness, thinning, major, minor, zone.
      constexpr unsigned int nk = dim - 1, stride = nk + 5;
      std::vector<double>    flat;
      for (std::size_t c = 0; c < cols.size(); ++c)
        {
          for (const auto k : keys[c])
            flat.push_back(k);
          flat.insert(flat.end(),
                      {cols[c].thickness,
                       100. * (1. - cols[c].thickness / t0),
                       cols[c].major,
                       cols[c].minor,
                       double(static_cast<int>(cols[c].zone))});
        }
      flat = Utilities::MPI::broadcast(state.comm, flat, 0);
      std::map<Key, std::size_t> index;
      for (std::size_t i = 0; i < flat.size(); i += stride)
        {
          Key k;
          for (unsigned int d = 0; d < nk; ++d)
            k[d] = static_cast<long long>(flat[i + d]);
          index[k] = i + nk;
        }
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                           state.dof_handler,
                                           support);
      std::array<VectorType, 5> owned;
      for (auto &v : owned)
        v.reinit(state.owned, state.comm);
      const auto                          &fe = state.dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int j = 0; j < dofs.size(); ++j)
              if (fe.system_to_component_index(j).first == 0 &&
                  state.owned.is_element(dofs[j]))
                {
                  const auto it = index.find(key(support[dofs[j]]));
                  if (it == index.end())
                    continue;
                  for (unsigned int f = 0; f < 5; ++f)
                    owned[f][dofs[j]] = flat[it->second + f];
                }
          }
      for (unsigned int f = 0; f < 5; ++f)
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

    template <int dim>
    void SheetMeasures<dim>::write_csv(const std::string &directory,
                                       const std::string &name) const
    {
      if (cols.empty())
        return; // not rank 0
      std::ostringstream f;
      f << "reference_radius,reference_angle,r,z,thickness,thinning_percent,"
           "major_strain,minor_strain,damage,zone,zone_name,rim\n";
      f.precision(8);
      for (const auto &c : cols)
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
