#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/cell_scatter.h>
#include <formsolve/solver/cell_tangent.h>

#include <algorithm>
#include <limits>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;
    using model::CellKinematics;
    using model::ShapeStrain;

    namespace
    {
      /// tr(D) + ln(dV/dV0)/dt at the points of @p k (reinit'ed, with the
      /// reference mapping): the volumetric rate with the accumulated volume
      /// error corrected (doc/theory.md, eq. 5).
      template <int dim>
      void volumetric_rates(const CellKinematics<dim>          &k,
                            const VectorType                   &v,
                            const double                        dt,
                            const double                        offset,
                            std::vector<SymmetricTensor<2, 3>> &D,
                            std::vector<double>                &rates)
      {
        k.rates(v, D);
        rates.resize(k.n_points());
        for (unsigned int q = 0; q < k.n_points(); ++q)
          {
            rates[q] = trace(D[q]);
            if (dt > 0)
              rates[q] += (std::log(k.dV(q) / k.dV_reference(q)) - offset) / dt;
          }
      }

      /// Mean of ln(dV/dV0) over the points of @p k (reinitialised).
      template <int dim>
      double log_volume_ratio(const CellKinematics<dim> &k)
      {
        double sum = 0;
        for (unsigned int q = 0; q < k.n_points(); ++q)
          sum += std::log(k.dV(q) / k.dV_reference(q));
        return sum / k.n_points();
      }
    } // namespace

    template <int dim>
    Assembler<dim>::Assembler(const material::RigidViscoplastic &material,
                              const model::Kinematics<dim>      &kinematics,
                              const Mapping<dim>             &reference_mapping,
                              const unsigned int              degree,
                              const material::DamageCriteria *damage)
        : material(material)
        , kinematics(kinematics)
        , reference_mapping(reference_mapping)
        , damage(damage)
        , full(degree + 1)
        , reduced(degree)
        , product_form(material.isotropic())
    {}

    template <int dim>
    double
    Assembler<dim>::assemble_body(const DoFHandler<dim>           &dof_handler,
                                  const Mapping<dim>              &mapping,
                                  const AffineConstraints<double> &constraints,
                                  const VectorType                &v,
                                  const HistoryStorage<dim>       &history,
                                  const double                     dt,
                                  const bool                       newton,
                                  MatrixType                      *matrix,
                                  VectorType                      &residual,
                                  DualStress                      *dual,
                                  const CellScatter<dim> *scatter) const
    {
      const auto         &fe = dof_handler.get_fe();
      const unsigned int  n  = fe.n_dofs_per_cell();
      CellKinematics<dim> kf(kinematics, mapping, fe, full);
      CellKinematics<dim> kr(kinematics,
                             mapping,
                             fe,
                             reduced,
                             update_default,
                             &reference_mapping);

      CellTangent<dim>                     tangent(fe,
                               kf.n_points(),
                               kr.n_points(),
                               kinematics.axisymmetric());
      FullMatrix<double>                   K(n, n);
      Vector<double>                       r(n);
      std::vector<SymmetricTensor<2, 3>>   D, Dr;
      std::vector<ShapeStrain>             B;
      std::vector<double>                  tr(n), s(n), u(n), div_v;
      std::vector<types::global_dof_index> dofs(n);
      const double                         Kv     = material.bulk_viscosity();
      double                               f_int2 = 0;

      if (matrix)
        *matrix = 0;
      residual = 0;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            kf.reinit(cell);
            kr.reinit(cell);
            r = 0;
            kf.rates(v, D);
            const auto h = history.get_data(cell);
            for (unsigned int q = 0; q < kf.n_points(); ++q)
              {
                const auto m =
                  material.evaluate(D[q], h[q]->strain, dt, newton);
                const double dV = kf.dV(q);
                kf.shape_strains(q, B);
                // Stress-velocity linearisation: (4/9) s/rate^3 D'(x)D' becomes
                // its symmetric part with one D' replaced by rate w.
                SymmetricTensor<2, 3> w_rate = m.strain_rate_deviator;
                if (dual)
                  w_rate = dual->trial(cell->active_cell_index(),
                                       q,
                                       m.strain_rate_deviator,
                                       material.cutoff_rate(),
                                       material.smooth_rigid_zone()) *
                           m.dual_rate;
                // d s'/dD = 2 mu P_dev + beta D' (x) D'  (doc/theory.md,
                // eq. 4, 4b): s = B : D', u = beta_h/2 s + beta_p t with
                // t = B : w.
                const double mu     = m.viscosity * dV;
                const double beta_h = (m.beta - m.beta_plastic) * dV;
                const double beta_p = 0.5 * m.beta_plastic * dV;
                for (unsigned int i = 0; i < n; ++i)
                  {
                    r[i] += B[i].contract(m.deviatoric_stress) * dV;
                    if (matrix)
                      {
                        s[i] = B[i].contract(m.strain_rate_deviator);
                        u[i] = 0.5 * beta_h * s[i] +
                               beta_p * (dual ? B[i].contract(w_rate) : s[i]);
                      }
                  }
                if (matrix && product_form)
                  tangent.add_deviatoric(q, B, mu, s, u);
                else if (matrix)
                  tangent.add_general(q, B, material.tangent(m, w_rate) * dV);
              }
            // Incompressibility by penalty, reduced integration against
            // locking.
            volumetric_rates(kr, v, dt, h[0]->volume_offset, Dr, div_v);
            for (unsigned int q = 0; q < kr.n_points(); ++q)
              {
                const double dV = kr.dV(q);
                kr.shape_strains(q, B);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    tr[i] = B[i].trace();
                    r[i] += Kv * div_v[q] * tr[i] * dV;
                  }
                if (matrix)
                  tangent.add_volumetric(q, tr, Kv * dV);
              }
            if (matrix)
              tangent.finish(K);
            f_int2 += r.norm_sqr();
            cell->get_dof_indices(dofs);
            if (matrix && scatter && scatter->maps(cell->active_cell_index()))
              {
                scatter->add(cell->active_cell_index(), K, *matrix);
                constraints.distribute_local_to_global(r, dofs, residual);
              }
            else if (matrix)
              constraints.distribute_local_to_global(K,
                                                     r,
                                                     dofs,
                                                     *matrix,
                                                     residual);
            else
              constraints.distribute_local_to_global(r, dofs, residual);
          }

      if (matrix)
        matrix->compress(VectorOperation::add);
      residual.compress(VectorOperation::add);
      return std::sqrt(Utilities::MPI::sum(
        f_int2,
        dof_handler.get_triangulation().get_communicator()));
    }

    template <int dim>
    void Assembler<dim>::initialize_history(const DoFHandler<dim> &dof_handler,
                                            HistoryStorage<dim> &history) const
    {
      for (const auto &cell :
           dof_handler.get_triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          history.initialize(cell, full.size());
    }

    template <int dim>
    void Assembler<dim>::update_history(const DoFHandler<dim> &dof_handler,
                                        const Mapping<dim>    &mapping,
                                        const VectorType      &v,
                                        const double           dt,
                                        HistoryStorage<dim>   &history) const
    {
      const auto         &fe = dof_handler.get_fe();
      CellKinematics<dim> kf(kinematics, mapping, fe, full, update_jacobians);
      CellKinematics<dim> kr(kinematics,
                             mapping,
                             fe,
                             reduced,
                             update_default,
                             &reference_mapping);
      std::vector<SymmetricTensor<2, 3>> D, Dr;
      std::vector<double>                div_v;
      const double                       Kv   = material.bulk_viscosity();
      const auto                        &flow = material.flow_stress();

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            kf.reinit(cell);
            kr.reinit(cell);
            kf.rates(v, D);
            auto h = history.get_data(cell);
            volumetric_rates(kr, v, dt, h[0]->volume_offset, Dr, div_v);
            double mean_div = 0, volume = 0;
            for (unsigned int q = 0; q < kr.n_points(); ++q)
              {
                mean_div += div_v[q] * kr.dV(q);
                volume += kr.dV(q);
              }
            const double mean_stress = Kv * mean_div / volume;

            for (unsigned int q = 0; q < kf.n_points(); ++q)
              {
                const auto r = material.evaluate(D[q], h[q]->strain, dt, false);
                if (damage)
                  {
                    const auto d =
                      damage->increment(r.deviatoric_stress,
                                        mean_stress,
                                        dt * r.equivalent_strain_rate);
                    h[q]->oyane += d.oyane;
                    h[q]->cockcroft_latham += d.cockcroft_latham;
                  }
                h[q]->strain += dt * r.equivalent_strain_rate;
                h[q]->strain_rate = r.equivalent_strain_rate;
                h[q]->flow_stress =
                  flow.value(h[q]->strain,
                             std::max(r.equivalent_strain_rate, 1e-300));
                h[q]->mean_stress = mean_stress;
                // Through-thickness direction: the mapped last reference axis
                // (the layer direction of the sheet mesh).
                const Tensor<1, 3> t = kf.mapped_axis(q, dim - 1);
                h[q]->thickness_strain += dt * (t * (D[q] * t));
              }
          }
    }

    template <int dim>
    double Assembler<dim>::integrate(const DoFHandler<dim>     &dof_handler,
                                     const Mapping<dim>        &mapping,
                                     const HistoryStorage<dim> *history,
                                     const HistoryField         field) const
    {
      CellKinematics<dim> k(kinematics, mapping, dof_handler.get_fe(), full);
      double              sum = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k.reinit(cell);
            for (unsigned int q = 0; q < k.n_points(); ++q)
              sum += (history ? history->get_data(cell)[q].get()->*field : 1.) *
                     k.dV(q);
          }
      return Utilities::MPI::sum(
        sum,
        dof_handler.get_triangulation().get_communicator());
    }

    template <int dim>
    double Assembler<dim>::volume(const DoFHandler<dim> &dof_handler,
                                  const Mapping<dim>    &mapping) const
    {
      return integrate(dof_handler,
                       mapping,
                       nullptr,
                       &simulation::QuadraturePointHistory::strain);
    }

    template <int dim>
    double Assembler<dim>::history_integral(const DoFHandler<dim> &dof_handler,
                                            const Mapping<dim>    &mapping,
                                            const HistoryStorage<dim> &history,
                                            const HistoryField field) const
    {
      return integrate(dof_handler, mapping, &history, field);
    }

    template <int dim>
    HistoryMaximum<dim>
    Assembler<dim>::history_maximum(const DoFHandler<dim>     &dof_handler,
                                    const Mapping<dim>        &mapping,
                                    const HistoryStorage<dim> &history,
                                    const HistoryField         field) const
    {
      const MPI_Comm comm  = dof_handler.get_triangulation().get_communicator();
      double         local = -std::numeric_limits<double>::max();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &h : history.get_data(cell))
            local = std::max(local, h.get()->*field);
      HistoryMaximum<dim> m;
      m.value = Utilities::MPI::max(local, comm);
      // Where: of the points with the largest value (up to round-off, which
      // differs between partitions), the first in the canonical order.
      FEValues<dim> fv(mapping,
                       dof_handler.get_fe(),
                       full,
                       update_quadrature_points);
      bool          found = false;
      Point<dim>    best;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto h      = history.get_data(cell);
            bool       reinit = true;
            for (unsigned int q = 0; q < h.size(); ++q)
              if (model::ties(h[q].get()->*field, m.value))
                {
                  if (reinit)
                    fv.reinit(cell), reinit = false;
                  if (!found || model::precedes(fv.quadrature_point(q), best))
                    best = fv.quadrature_point(q), found = true;
                }
          }
      const auto candidates =
        Utilities::MPI::all_gather(comm, std::make_pair(found, best));
      found = false;
      for (const auto &[f, p] : candidates)
        if (f && (!found || model::precedes(p, m.location)))
          m.location = p, found = true;
      return m;
    }

    template <int dim>
    double Assembler<dim>::internal_power(const DoFHandler<dim> &dof_handler,
                                          const Mapping<dim>    &mapping,
                                          const VectorType      &v,
                                          const HistoryStorage<dim> &history,
                                          const double               dt) const
    {
      const auto                        &fe = dof_handler.get_fe();
      CellKinematics<dim>                kf(kinematics, mapping, fe, full);
      CellKinematics<dim>                kr(kinematics, mapping, fe, reduced);
      std::vector<SymmetricTensor<2, 3>> D, Dr;
      double                             power = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            kf.reinit(cell);
            kr.reinit(cell);
            kf.rates(v, D);
            kr.rates(v, Dr);
            const auto h = history.get_data(cell);
            for (unsigned int q = 0; q < kf.n_points(); ++q)
              power += material.evaluate(D[q], h[q]->strain, dt, false)
                         .deviatoric_stress *
                       D[q] * kf.dV(q);
            for (unsigned int q = 0; q < kr.n_points(); ++q)
              power += material.bulk_viscosity() * trace(Dr[q]) * trace(Dr[q]) *
                       kr.dV(q);
          }
      return Utilities::MPI::sum(
        power,
        dof_handler.get_triangulation().get_communicator());
    }

    template <int dim>
    void
    Assembler<dim>::exchange_volume_offsets(const DoFHandler<dim> &dof_handler,
                                            const Mapping<dim>    &mapping,
                                            HistoryStorage<dim> &history) const
    {
      CellKinematics<dim> kr(kinematics,
                             mapping,
                             dof_handler.get_fe(),
                             reduced,
                             update_default,
                             &reference_mapping);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            kr.reinit(cell);
            const double ratio = log_volume_ratio(kr);
            auto         h     = history.get_data(cell);
            // The transfer may leave a coarsened cell's values unequal.
            double stored = 0;
            for (const auto &p : h)
              stored += p->volume_offset / h.size();
            for (auto &p : h)
              p->volume_offset = ratio - stored;
          }
    }

#define INSTANTIATE(dim) template class Assembler<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
