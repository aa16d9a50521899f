// Rank 0's part of SheetMeasures::measure: the node columns assembled from
// every rank's flat records, and the summary of the sheet over them
// (thinning, safety zones, rim radius and draw-in; doc/theory.md, section 11).
#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/postprocess/sheet_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /// A node column of the sheet while the ranks' records are summed: its
      /// top and bottom nodes, and the mid-plane cell corners that meet there.
      template <int dim>
      struct Column
      {
        bool                   top = false, bottom = false, rim = false;
        bool                   top_touching = false, bottom_touching = false;
        dealii::Point<dim>     x_top, x_bottom, mid;
        dealii::Tensor<1, dim> normal;
        double                 major = 0, minor = 0, damage = 0;
        unsigned int           n = 0;
      };

      /// The measures of a column with a top and a bottom node at reference
      /// position @p X (all but the safety zone).
      template <int dim>
      SheetColumn<dim> measures(const Column<dim>        &c,
                                const dealii::Point<dim> &X)
      {
        SheetColumn<dim> s;
        s.reference_radius = dim == 2 ? X[0] : std::hypot(X[0], X[1]);
        s.reference_angle =
          dim == 2 ? 0. : std::atan2(X[1], X[0]) * 180. / M_PI;
        const dealii::Tensor<1, dim> across = c.x_top - c.x_bottom;
        if (c.n > 0)
          {
            s.mid       = c.mid / double(c.n);
            s.thickness = std::abs(across * (c.normal / c.normal.norm()));
            s.major     = c.major / c.n;
            s.minor     = c.minor / c.n;
          }
        else // no mid-plane cell corner here (e.g. a Q2 mid-edge node)
          {
            s.mid       = c.x_bottom + 0.5 * across;
            s.thickness = across.norm();
          }
        s.damage   = c.damage;
        s.rim      = c.rim;
        s.squeezed = c.top_touching && c.bottom_touching;
        s.top      = std::max(c.x_top[dim - 1], c.x_bottom[dim - 1]);
        s.bottom   = std::min(c.x_top[dim - 1], c.x_bottom[dim - 1]);
        return s;
      }
    } // namespace

    template <int dim>
    void SheetMeasures<dim>::assemble_columns(
      const std::vector<std::vector<double>> &all_nodes,
      const std::vector<std::vector<double>> &all_cells,
      const std::vector<std::vector<double>> &all_damages)
    {
      constexpr unsigned int           nk = dim - 1, nc = n_corners;
      std::map<Key, Column<dim>>       columns;
      std::vector<std::array<Key, nc>> mid_cells; // corner keys
      auto read_key = [&](const std::vector<double> &v, std::size_t &i) {
        Key k;
        for (unsigned int d = 0; d < nk; ++d)
          k[d] = static_cast<long long>(v[i++]);
        return k;
      };
      for (const auto &v : all_nodes)
        for (std::size_t i = 0; i < v.size();)
          {
            auto        &c     = columns[read_key(v, i)];
            const double side  = v[i++];
            const bool   touch = v[i++] != 0.;
            Point<dim>   p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = v[i++];
            if (side == 0.)
              c.bottom = true, c.x_bottom = p, c.bottom_touching = touch;
            else if (side == 1.)
              c.top = true, c.x_top = p, c.top_touching = touch;
            else
              c.rim = true;
          }
      for (const auto &v : all_cells)
        for (std::size_t i = 0; i < v.size();)
          {
            std::array<Key, n_corners>        k;
            std::array<Point<dim>, n_corners> p;
            for (unsigned int c = 0; c < nc; ++c)
              {
                k[c] = read_key(v, i);
                for (unsigned int d = 0; d < dim; ++d)
                  p[c][d] = v[i++];
              }
            mid_cells.push_back(k);
            const double   major = v[i++], minor = v[i++];
            Tensor<1, dim> n;
            for (unsigned int d = 0; d < dim; ++d)
              n[d] = v[i++];
            for (unsigned int c = 0; c < nc; ++c)
              {
                auto &col = columns[k[c]];
                col.mid += p[c];
                col.normal += n;
                col.major += major;
                col.minor += minor;
                ++col.n;
              }
          }
      for (const auto &v : all_damages)
        for (std::size_t i = 0; i < v.size();)
          {
            std::array<Key, n_corners> k;
            for (unsigned int c = 0; c < nc; ++c)
              k[c] = read_key(v, i);
            const double d = v[i++];
            for (unsigned int c = 0; c < nc; ++c)
              columns[k[c]].damage = std::max(columns[k[c]].damage, d);
          }

      for (const auto &[k, c] : columns)
        if (c.top && c.bottom)
          {
            Point<dim> X;
            for (unsigned int d = 0; d < nk; ++d)
              X[d] = k[d] * quantum;
            SheetColumn<dim> s = measures(c, X);
            s.zone             = flc.zone(s.minor, s.major, s.damage);
            cols.push_back(s);
            keys.push_back(k);
          }
      cell_centre_thickness(mid_cells);
    }

    template <int dim>
    void SheetMeasures<dim>::cell_centre_thickness(
      const std::vector<std::array<Key, n_corners>> &mid_cells)
    {
      // The nodal positions carry a checkerboard mode of the thickness that
      // the volume constraint at the cell centres does not see; it is
      // largest at the axis of the axisymmetric model, whose node the
      // volume element 2 pi r weights by zero (doc/theory.md, section 11).
      // Each cell's centre thickness is the mean of its corners', and a
      // column gets the mean of its cells', at every column alike.
      std::map<Key, std::size_t> index;
      for (std::size_t i = 0; i < keys.size(); ++i)
        index[keys[i]] = i;
      std::vector<double>       sum(cols.size(), 0.);
      std::vector<unsigned int> count(cols.size(), 0);
      for (const auto &corners : mid_cells)
        {
          std::array<std::size_t, n_corners> at;
          double                             t        = 0;
          bool                               complete = true;
          for (unsigned int c = 0; c < n_corners && complete; ++c)
            {
              const auto it = index.find(corners[c]);
              complete      = it != index.end();
              if (complete)
                at[c] = it->second, t += cols[it->second].thickness;
            }
          if (!complete)
            continue;
          for (const auto i : at)
            sum[i] += t / n_corners, ++count[i];
        }
      for (std::size_t i = 0; i < cols.size(); ++i)
        if (count[i] > 0)
          cols[i].thickness = sum[i] / count[i];
    }

    template <int dim>
    SheetSummary<dim> SheetMeasures<dim>::summarise()
    {
      constexpr double nan   = std::numeric_limits<double>::quiet_NaN();
      double           r_max = 0;
      for (const auto &c : cols)
        r_max = std::max(r_max, c.reference_radius);
      // Without rim nodes between the surfaces (one layer of Q1), the rim
      // is where the blank radius is largest.
      const bool flagged = std::any_of(cols.begin(),
                                       cols.end(),
                                       [](const auto &c) { return c.rim; });
      if (!flagged)
        for (auto &c : cols)
          c.rim = c.reference_radius > r_max - 1e-6;

      SheetSummary<dim> s;
      s.blank_radius  = r_max;
      s.min_thickness = std::numeric_limits<double>::max();
      for (const auto &c : cols)
        {
          s.min_thickness = std::min(s.min_thickness, c.thickness);
          ++s.zone_count[static_cast<int>(c.zone)];
        }
      // Where: of the thinnest columns (up to round-off), the first in
      // the canonical order, so that no partition decides.
      bool found = false;
      for (const auto &c : cols)
        if (model::ties(c.thickness, s.min_thickness) &&
            (!found || model::precedes(c.mid, s.min_thickness_location)))
          {
            s.min_thickness_radius   = c.reference_radius;
            s.min_thickness_location = c.mid;
            found                    = true;
          }
      s.max_thinning       = 100. * (1. - s.min_thickness / t0);
      double max_thickness = 0, bottom = std::numeric_limits<double>::max(),
             rim_top = -bottom, usage = 0;
      for (const auto &c : cols)
        {
          max_thickness = std::max(max_thickness, c.thickness);
          bottom        = std::min(bottom, c.bottom);
          if (c.rim)
            rim_top = std::max(rim_top, c.top);
          // Stretched beyond the curve's own scale only: a column with no
          // positive major strain uses none of the limit. Ties go to the
          // first in the canonical order, so that no partition decides.
          const double u = c.major > 0 && flc.major(c.minor) > 0
                             ? c.major / flc.major(c.minor)
                             : 0.;
          if (u > usage || (u > 0 && model::ties(u, usage) &&
                            model::precedes(c.mid, s.flc_location)))
            {
              usage          = std::max(u, usage);
              s.flc_radius   = c.reference_radius;
              s.flc_angle    = c.reference_angle;
              s.flc_location = c.mid;
            }
        }
      s.max_thickening = 100. * (max_thickness / t0 - 1.);
      s.flc_margin     = 100. * (1. - usage);
      s.cup_height     = rim_top - bottom;
      std::vector<const SheetColumn<dim> *> rim;
      for (const auto &c : cols)
        if (c.rim)
          rim.push_back(&c);
      std::sort(rim.begin(), rim.end(), [](const auto *a, const auto *b) {
        return a->reference_angle < b->reference_angle;
      });
      auto radius = [](const SheetColumn<dim> &c) {
        return dim == 2 ? c.mid[0] : std::hypot(c.mid[0], c.mid[1]);
      };
      for (const double phi :
           (dim == 2 ? std::vector<double>{0.}
                     : std::vector<double>{0., diagonal, 90.}))
        {
          double r = nan, R = nan;
          for (std::size_t i = 0; i < rim.size(); ++i)
            {
              const double a = rim[i]->reference_angle;
              if (std::abs(a - phi) < 1e-6)
                r = radius(*rim[i]), R = rim[i]->reference_radius;
              else if (i + 1 < rim.size() && a < phi &&
                       rim[i + 1]->reference_angle > phi)
                {
                  const double w =
                    (phi - a) / (rim[i + 1]->reference_angle - a);
                  r = (1 - w) * radius(*rim[i]) + w * radius(*rim[i + 1]);
                  R = (1 - w) * rim[i]->reference_radius +
                      w * rim[i + 1]->reference_radius;
                }
            }
          s.rim_radius.push_back(r);
          s.draw_in.push_back(R - r);
        }
      return s;
    }

#define INSTANTIATE(dim)                              \
  template void SheetMeasures<dim>::assemble_columns( \
    const std::vector<std::vector<double>> &,         \
    const std::vector<std::vector<double>> &,         \
    const std::vector<std::vector<double>> &);        \
  template SheetSummary<dim> SheetMeasures<dim>::summarise();
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
