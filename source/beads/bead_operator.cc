#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/beads/bead_model.h>
#include <formsolve/beads/bead_operator.h>
#include <formsolve/model/dimensions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace beads
  {
    using namespace dealii;

    namespace
    {
      /// (2/pi) atan(x / v0) and its derivative, as friction regularises.
      std::pair<double, double> regularised(const double x, const double v0)
      {
        const double y = x / v0;
        return {2. / M_PI * std::atan(y), 2. / M_PI / (v0 * (1. + y * y))};
      }

      double along(const std::vector<double> &values, const double s)
      {
        return values.size() == 1 ? values[0]
                                  : (1 - s) * values[0] + s * values[1];
      }

    } // namespace

    template <int dim>
    BeadOperator<dim>::BeadOperator(const parameters::Run             &prm,
                                    const material::RigidViscoplastic &law,
                                    const model::Kinematics<dim>      &k)
        : params(prm.tools.draw_beads)
        , t0(prm.geometry.thickness)
    {
      const double r = law.mean_r();
      for (const auto &bead : params.beads)
        {
          lines.push_back(bead_points<dim>(bead,
                                           k,
                                           t0,
                                           prm.geometry.model,
                                           prm.geometry.blank_width));
          // The flow stress at the mean strain of the passage, at the rate
          // of passing the arcs at the punch speed; plane strain with the
          // mean r-value (Hill's normal anisotropy).
          const BeadGeometry g{bead.bead_radius,
                               bead.shoulder_radius,
                               bead.friction};
          const double       eps = passage_strain(g, t0);
          const double       arc = 2 * wrap_angle(g, bead.height, t0) *
                             (bead.bead_radius + bead.shoulder_radius + t0);
          const double rate = prm.tools.punch_speed * eps / std::max(arc, t0);
          sigma_ps.push_back(law.flow_stress().value(eps / 2, rate) * (1 + r) /
                             std::sqrt(1 + 2 * r));
        }
      force.resize(lines.size());
      open.resize(lines.size());
      on_sheet.resize(lines.size());
    }

    template <int dim>
    void BeadOperator<dim>::begin_step(const state::State<dim> &state)
    {
      hits.clear();
      opening_force = 0;
      if (!any())
        return;
      std::vector<std::vector<double>> clear_die, count_die, clear_holder,
        count_holder;
      const unsigned int first = hits.size();
      locate(state, -1, hits, clear_die, count_die);
      const unsigned int holder_side = hits.size();
      locate(state, +1, hits, clear_holder, count_holder);
      for (auto *v : {&clear_die, &count_die, &clear_holder, &count_holder})
        for (auto &x : *v)
          Utilities::MPI::sum(x, state.comm, x);
      // A point on an edge between faces is found on each: they share it.
      for (unsigned int i = first; i < hits.size(); ++i)
        hits[i].share =
          0.5 / (i < holder_side ? count_die
                                 : count_holder)[hits[i].bead][hits[i].point];
      for (unsigned int b = 0; b < lines.size(); ++b)
        {
          std::vector<std::vector<double>> clear = {clear_die[b],
                                                    clear_holder[b]},
                                           count = {count_die[b],
                                                    count_holder[b]};
          set_forces(b, clear, count);
          for (unsigned int q = 0; q < lines[b].size(); ++q)
            opening_force += on_sheet[b][q] * lines[b][q].weight * open[b][q];
        }
    }

    template <int dim>
    void BeadOperator<dim>::check_scene(const state::State<dim> &state)
    {
      begin_step(state);
      for (unsigned int b = 0; b < lines.size(); ++b)
        for (unsigned int q = 0; q < lines[b].size(); ++q)
          {
            const Point<dim>  &x = lines[b][q].plan;
            std::ostringstream where;
            where << "Tools/Draw beads/" << params.beads[b].name
                  << "/Line: the point (" << x[0];
            if (dim == 3)
              where << ", " << x[1];
            where << ") of the bead ";
            AssertThrow(on_sheet[b][q] > 0,
                        ExcMessage(where.str() +
                                   "lies outside the blank; a bead acts on "
                                   "the flange between die and holder"));
            Point<dim> at = x;
            at[dim - 1]   = 0;
            for (const unsigned int t :
                 {state.tools.die_index(), state.tools.holder_index()})
              AssertThrow(state.tools[t].lateral_distance(at) > 0,
                          ExcMessage(where.str() + "lies outside the face of " +
                                     state.tools[t].name() +
                                     " (in its opening): a bead sits on the "
                                     "flange, where die and holder close"));
          }
    }

    template <int dim>
    void
    BeadOperator<dim>::set_forces(const unsigned int                      b,
                                  const std::vector<std::vector<double>> &clear,
                                  const std::vector<std::vector<double>> &count)
    {
      const auto        &bead = params.beads[b];
      const unsigned int n    = lines[b].size();
      force[b].assign(n, 0.);
      open[b].assign(n, 0.);
      on_sheet[b].assign(n, 0.);
      for (unsigned int q = 0; q < n; ++q)
        {
          if (count[0][q] == 0 && count[1][q] == 0)
            continue; // no sheet under this point (yet, or any more)
          on_sheet[b][q] = 1;
          // Clearance between the tools and the sheet: 0 with the holder
          // closed on it.
          double c = 0;
          for (unsigned int side = 0; side < 2; ++side)
            if (count[side][q] > 0)
              c += std::max(clear[side][q] / count[side][q], 0.);
          const double p = std::clamp(bead.height - c, 0., bead.height);
          if (bead.model == parameters::BeadModel::forces)
            {
              const double s = lines[b][q].along;
              force[b][q]    = along(bead.restraining, s) * p / bead.height;
              open[b][q]     = along(bead.opening, s) * p / bead.height;
            }
          else
            {
              const auto f = bead_forces({bead.bead_radius,
                                          bead.shoulder_radius,
                                          bead.friction},
                                         p,
                                         t0,
                                         sigma_ps[b]);
              force[b][q]  = f.restraining;
              open[b][q]   = f.opening;
            }
        }
    }

    template <int dim>
    double BeadOperator<dim>::v_normal(const Hit &h, const VectorType &v) const
    {
      double vn = 0;
      for (unsigned int i = 0; i < h.dofs.size(); ++i)
        vn += h.g[i] * v(h.dofs[i]);
      return vn;
    }

    template <int dim>
    void BeadOperator<dim>::add(const VectorType                &v,
                                const AffineConstraints<double> &constraints,
                                const double                     v0,
                                const bool                       newton,
                                MatrixType                      *K,
                                VectorType                      *r) const
    {
      if (!any())
        return;
      Vector<double>     rl;
      FullMatrix<double> Kl;
      for (const auto &h : hits)
        {
          const double F =
            force[h.bead][h.point] * lines[h.bead][h.point].weight * h.share;
          if (F == 0)
            continue;
          const double vn         = v_normal(h, v);
          const auto [reg, slope] = regularised(vn, v0);
          const unsigned int n    = h.dofs.size();
          // r = internal - external, the bead's force on the sheet being
          // -F reg(v.n) n: r += F reg g.
          if (r)
            {
              rl.reinit(n);
              for (unsigned int i = 0; i < n; ++i)
                rl(i) = F * reg * h.g[i];
              constraints.distribute_local_to_global(rl, h.dofs, *r);
            }
          if (K)
            {
              // Newton: d(F reg)/d(v.n); secant: F reg / (v.n).
              const double k =
                F * (newton                      ? slope
                     : std::abs(vn) > 1e-12 * v0 ? reg / vn
                                                 : 2. / M_PI / v0);
              Kl.reinit(n, n);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  Kl(i, j) = k * h.g[i] * h.g[j];
              constraints.distribute_local_to_global(Kl, h.dofs, h.dofs, *K);
            }
        }
      if (r)
        r->compress(VectorOperation::add);
      if (K)
        K->compress(VectorOperation::add);
    }

    template <int dim>
    std::vector<state::BeadRecord>
    BeadOperator<dim>::rates(const VectorType &v,
                             const double      v0,
                             const MPI_Comm    comm) const
    {
      const unsigned int  nb = lines.size();
      std::vector<double> sums(3 * nb, 0.);
      for (const auto &h : hits)
        {
          const double w  = lines[h.bead][h.point].weight * h.share;
          const double F  = force[h.bead][h.point] * w;
          const double vn = v_normal(h, v);
          const double g  = regularised(vn, v0).first;
          sums[3 * h.bead] += F * std::abs(g);
          sums[3 * h.bead + 1] += F * g * vn;
          sums[3 * h.bead + 2] += w * std::abs(vn);
        }
      Utilities::MPI::sum(sums, comm, sums);
      std::vector<state::BeadRecord> out(nb);
      for (unsigned int b = 0; b < nb; ++b)
        {
          double length = 0;
          for (unsigned int q = 0; q < lines[b].size(); ++q)
            {
              length += on_sheet[b][q] * lines[b][q].weight;
              out[b].opening +=
                on_sheet[b][q] * lines[b][q].weight * open[b][q];
            }
          out[b].force      = sums[3 * b];
          out[b].power      = sums[3 * b + 1];
          out[b].drawn_rate = length > 0 ? sums[3 * b + 2] / length : 0.;
        }
      return out;
    }

#define INSTANTIATE(dim) template class BeadOperator<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace beads
} // namespace formsolve
