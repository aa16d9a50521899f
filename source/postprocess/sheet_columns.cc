// The owners' part of SheetMeasures::measure: the node columns assembled from
// the records sent to the rank that owns them, the cell-centre thickness, and
// the summary of the sheet by reductions over the ranks (thinning, safety
// zones, rim radius and draw-in; doc/theory.md, section 11).
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
      const Outbox                             &received,
      std::map<unsigned int, std::vector<Key>> &corners)
    {
      constexpr unsigned int     nk = dim - 1;
      std::map<Key, Column<dim>> columns;
      auto read_point = [&](const std::vector<double> &v, std::size_t &i) {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = v[i++];
        return p;
      };
      for (const auto &[rank, v] : received)
        for (std::size_t i = 0; i < v.size();)
          {
            const auto kind = static_cast<Kind>(static_cast<int>(v[i++]));
            Key        k;
            for (unsigned int d = 0; d < nk; ++d)
              k[d] = static_cast<long long>(v[i++]);
            auto &c = columns[k];
            if (kind == node_record)
              {
                const double     side  = v[i++];
                const bool       touch = v[i++] != 0.;
                const Point<dim> p     = read_point(v, i);
                if (side == 0.)
                  c.bottom = true, c.x_bottom = p, c.bottom_touching = touch;
                else if (side == 1.)
                  c.top = true, c.x_top = p, c.top_touching = touch;
                else
                  c.rim = true;
              }
            else if (kind == corner_record)
              {
                corners[rank].push_back(k);
                c.mid += read_point(v, i);
                c.major += v[i++];
                c.minor += v[i++];
                c.normal += read_point(v, i);
                ++c.n;
              }
            else
              c.damage = std::max(c.damage, v[i++]);
          }
      cols.clear();
      keys.clear();
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
    }

    template <int dim>
    void SheetMeasures<dim>::cell_centre_thickness(
      const MPI_Comm                                  comm,
      const std::vector<std::array<Key, n_corners>>  &mid,
      const std::map<unsigned int, std::vector<Key>> &corners)
    {
      // The nodal positions carry a checkerboard mode of the thickness that
      // the volume constraint at the cell centres does not see; it is
      // largest at the axis of the axisymmetric model, whose node the
      // volume element 2 pi r weights by zero (doc/theory.md, section 11).
      // Each cell's centre thickness is the mean of its corners', and a
      // column gets the mean of its cells', at every column alike.
      constexpr double   nan     = std::numeric_limits<double>::quiet_NaN();
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      // The owners answer each corner record with its column's thickness.
      Outbox answers;
      for (const auto &[rank, ks] : corners)
        for (const auto &k : ks)
          {
            const std::size_t c = find(k);
            answers[rank].push_back(c < cols.size() ? cols[c].thickness : nan);
          }
      const Outbox thickness = exchange_records(comm, answers);
      // The cells' ranks send each corner its cell's centre thickness, in
      // the order of the corner records (NaN: a corner has no column).
      Outbox                              centres;
      std::map<unsigned int, std::size_t> next;
      for (const auto &corner : mid)
        {
          std::array<unsigned int, n_corners> owner;
          double                              t = 0;
          for (unsigned int c = 0; c < n_corners; ++c)
            {
              owner[c] = column_owner(corner[c], n_ranks);
              t += thickness.at(owner[c])[next[owner[c]]++];
            }
          for (unsigned int c = 0; c < n_corners; ++c)
            centres[owner[c]].push_back(t / n_corners);
        }
      std::vector<double>       sum(cols.size(), 0.);
      std::vector<unsigned int> count(cols.size(), 0);
      for (const auto &[rank, values] : exchange_records(comm, centres))
        for (std::size_t i = 0; i < values.size(); ++i)
          if (!std::isnan(values[i]))
            {
              const std::size_t c = find(corners.at(rank)[i]);
              sum[c] += values[i];
              ++count[c];
            }
      for (std::size_t i = 0; i < cols.size(); ++i)
        if (count[i] > 0)
          cols[i].thickness = sum[i] / count[i];
    }

    template <int dim>
    SheetSummary<dim> SheetMeasures<dim>::summarise(const MPI_Comm comm)
    {
      namespace mpi          = Utilities::MPI;
      constexpr double big   = std::numeric_limits<double>::max();
      double           r_max = 0;
      bool             rim   = false;
      for (const auto &c : cols)
        r_max = std::max(r_max, c.reference_radius), rim |= c.rim;
      r_max = mpi::max(r_max, comm);
      // Without rim nodes between the surfaces (one layer of Q1), the rim
      // is where the blank radius is largest.
      if (mpi::max(rim ? 1 : 0, comm) == 0)
        for (auto &c : cols)
          c.rim = c.reference_radius > r_max - 1e-6;

      SheetSummary<dim>   s;
      std::vector<double> zones(material::n_safety_zones, 0.);
      double              min_thickness = big, max_thickness = 0, bottom = big,
             rim_top = -big, usage = 0;
      for (const auto &c : cols)
        {
          min_thickness = std::min(min_thickness, c.thickness);
          max_thickness = std::max(max_thickness, c.thickness);
          bottom        = std::min(bottom, c.bottom);
          if (c.rim)
            rim_top = std::max(rim_top, c.top);
          zones[static_cast<int>(c.zone)] += 1;
          // Stretched beyond the curve's own scale only: a column with no
          // positive major strain uses none of the limit.
          if (c.major > 0 && flc.major(c.minor) > 0)
            usage = std::max(usage, c.major / flc.major(c.minor));
        }
      s.blank_radius  = r_max;
      s.min_thickness = mpi::min(min_thickness, comm);
      usage           = mpi::max(usage, comm);
      mpi::sum(zones, comm, zones);
      for (unsigned int z = 0; z < zones.size(); ++z)
        s.zone_count[z] = static_cast<unsigned int>(zones[z]);
      // Where: of the columns at the extreme (up to round-off), the first in
      // the canonical order, so that no partition decides.
      Candidate<dim> thin, near;
      for (const auto &c : cols)
        {
          if (model::ties(c.thickness, s.min_thickness) &&
              (!thin.valid || model::precedes(c.mid, thin.point)))
            thin = {true, c.mid, {c.reference_radius}};
          const double u = c.major > 0 && flc.major(c.minor) > 0
                             ? c.major / flc.major(c.minor)
                             : 0.;
          if (u > 0 && model::ties(u, usage) &&
              (!near.valid || model::precedes(c.mid, near.point)))
            near = {true, c.mid, {c.reference_radius, c.reference_angle}};
        }
      thin = first_in_order(comm, thin);
      near = first_in_order(comm, near);
      if (thin.valid)
        s.min_thickness_location = thin.point,
        s.min_thickness_radius   = thin.values[0];
      if (near.valid)
        s.flc_location = near.point, s.flc_radius = near.values[0],
        s.flc_angle = near.values[1];
      s.max_thinning   = 100. * (1. - s.min_thickness / t0);
      s.max_thickening = 100. * (mpi::max(max_thickness, comm) / t0 - 1.);
      s.flc_margin     = 100. * (1. - usage);
      s.cup_height     = mpi::max(rim_top, comm) - mpi::min(bottom, comm);
      rim_measures(comm, s);
      return s;
    }

    template <int dim>
    void SheetMeasures<dim>::rim_measures(const MPI_Comm     comm,
                                          SheetSummary<dim> &s) const
    {
      constexpr double nan    = std::numeric_limits<double>::quiet_NaN();
      auto             radius = [](const SheetColumn<dim> &c) {
        return dim == 2 ? c.mid[0] : std::hypot(c.mid[0], c.mid[1]);
      };
      // Per direction, this rank's rim column at its angle and the nearest
      // below and above it: (found, angle, current radius, reference radius)
      // each; the ranks' nearest decide.
      const std::vector<double> directions =
        dim == 2 ? std::vector<double>{0.}
                 : std::vector<double>{0., diagonal, 90.};
      std::vector<double> mine;
      for (const double phi : directions)
        {
          std::array<double, 12> b{
            {0, -1e300, nan, nan, 0, -1e300, nan, nan, 0, 1e300, nan, nan}};
          for (const auto &c : cols)
            if (c.rim)
              {
                const double a = c.reference_angle;
                const int slot = std::abs(a - phi) < 1e-6 ? 0 : a < phi ? 1 : 2;
                double   *x    = &b[4 * slot];
                if (slot == 2 ? a < x[1] : a > x[1])
                  x[0] = 1, x[1] = a, x[2] = radius(c),
                  x[3] = c.reference_radius;
              }
          mine.insert(mine.end(), b.begin(), b.end());
        }
      const auto all = Utilities::MPI::all_gather(comm, mine);
      for (std::size_t p = 0; p < directions.size(); ++p)
        {
          std::array<double, 12> g{
            {0, -1e300, nan, nan, 0, -1e300, nan, nan, 0, 1e300, nan, nan}};
          for (const auto &v : all)
            for (unsigned int slot = 0; slot < 3; ++slot)
              {
                const double *x = &v[12 * p + 4 * slot];
                double       *y = &g[4 * slot];
                if (x[0] != 0 && (slot == 2 ? x[1] < y[1] : x[1] > y[1]))
                  std::copy(x, x + 4, y);
              }
          double r = nan, R = nan;
          if (g[0] != 0)
            r = g[2], R = g[3];
          else if (g[4] != 0 && g[8] != 0)
            {
              const double w = (directions[p] - g[5]) / (g[9] - g[5]);
              r              = (1 - w) * g[6] + w * g[10];
              R              = (1 - w) * g[7] + w * g[11];
            }
          s.rim_radius.push_back(r);
          s.draw_in.push_back(R - r);
        }
    }

#define INSTANTIATE(dim)                                                      \
  template void SheetMeasures<dim>::assemble_columns(                         \
    const Outbox &,                                                           \
    std::map<unsigned int, std::vector<Key>> &);                              \
  template void SheetMeasures<dim>::cell_centre_thickness(                    \
    const MPI_Comm,                                                           \
    const std::vector<std::array<Key, n_corners>> &,                          \
    const std::map<unsigned int, std::vector<Key>> &);                        \
  template SheetSummary<dim> SheetMeasures<dim>::summarise(const MPI_Comm);   \
  template void              SheetMeasures<dim>::rim_measures(const MPI_Comm, \
                                                 SheetSummary<dim> &) const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
