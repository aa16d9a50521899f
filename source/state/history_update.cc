#include <formsolve/material/hill_orientation.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/volumetric_rate.h>

#include <algorithm>

namespace formsolve
{
  namespace state
  {
    using namespace dealii;
    using model::CellKinematics;

    template <int dim>
    HistoryUpdate<dim>::HistoryUpdate(
      const material::RigidViscoplastic &material,
      const model::Kinematics<dim>      &kinematics,
      const Mapping<dim>                &reference_mapping,
      const unsigned int                 degree,
      const material::DamageCriteria    *damage)
        : material(material)
        , kinematics(kinematics)
        , reference_mapping(reference_mapping)
        , damage(damage)
        , full(degree + 1)
        , reduced(degree)
    {}

    template <int dim>
    void HistoryUpdate<dim>::advance(const DoFHandler<dim> &dof_handler,
                                     const Mapping<dim>    &mapping,
                                     const VectorType      &v,
                                     const double           dt,
                                     HistoryStorage<dim>   &history) const
    {
      const auto                        &fe   = dof_handler.get_fe();
      const bool                         hill = !material.isotropic();
      CellKinematics<dim>                kf(kinematics,
                             mapping,
                             fe,
                             full,
                             update_jacobians,
                             hill ? &reference_mapping : nullptr);
      material::HillOrientation<dim>     orientation(material);
      CellKinematics<dim>                kr(kinematics,
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
            if (hill)
              orientation.reinit(kf);
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
                const auto r =
                  material.evaluate(D[q],
                                    h[q]->strain,
                                    dt,
                                    false,
                                    hill ? &orientation.map(q) : nullptr);
                if (damage)
                  {
                    const auto d = damage->increment(
                      r.deviatoric_stress,
                      mean_stress,
                      material::RigidViscoplastic::equivalent_stress(r),
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
    void HistoryUpdate<dim>::exchange_volume_offsets(
      const DoFHandler<dim> &dof_handler,
      const Mapping<dim>    &mapping,
      HistoryStorage<dim>   &history) const
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

#define INSTANTIATE(dim) template class HistoryUpdate<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
