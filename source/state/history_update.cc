#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/state/cell_points.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/projected_mean_stress.h>
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

    namespace
    {
      /// The element's penalty pressure sigma_m = K_v mean(div v) (MPa) at
      /// the reduced points of @p kr (reinitialised).
      template <int dim>
      double cell_pressure(const CellKinematics<dim>          &kr,
                           const VectorType                   &v,
                           const double                        dt,
                           const double                        offset,
                           const double                        Kv,
                           std::vector<SymmetricTensor<2, 3>> &Dr,
                           std::vector<double>                &div_v)
      {
        volumetric_rates(kr, v, dt, offset, Dr, div_v);
        double mean_div = 0, volume = 0;
        for (unsigned int q = 0; q < kr.n_points(); ++q)
          {
            mean_div += div_v[q] * kr.dV(q);
            volume += kr.dV(q);
          }
        return Kv * mean_div / volume;
      }
    } // namespace

    template <int dim>
    void
    HistoryUpdate<dim>::advance(const DoFHandler<dim>            &dof_handler,
                                const Mapping<dim>               &mapping,
                                const VectorType                 &v,
                                const double                      dt,
                                HistoryStorage<dim>              &history,
                                const material::PointFrames<dim> *frames) const
    {
      const auto &fe = dof_handler.get_fe();
      const bool  projected =
        damage && damage->mean_stress() == parameters::MeanStress::projected;
      // The sheet's normal (thickness strain) needs the Jacobians.
      CellPoints<dim>                    points(material,
                             kinematics,
                             mapping,
                             reference_mapping,
                             fe,
                             full,
                             reduced,
                             update_jacobians |
                               (projected ? update_values : update_default),
                             frames);
      CellKinematics<dim>               &kf = points.full();
      CellKinematics<dim>               &kr = points.reduced();
      std::vector<SymmetricTensor<2, 3>> Dr;
      std::vector<double>                div_v, cell_means, point_means;
      const double                       Kv = material.bulk_viscosity();
      ProjectedMeanStress<dim>           projection;
      if (projected)
        {
          cell_means.assign(dof_handler.get_triangulation().n_active_cells(),
                            0.);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                kr.reinit(cell);
                cell_means[cell->active_cell_index()] =
                  cell_pressure(kr,
                                v,
                                dt,
                                history.get_data(cell)[0]->volume_offset,
                                Kv,
                                Dr,
                                div_v);
              }
          projection.project(dof_handler, kf, cell_means, v);
        }

      points.for_each_owned(
        dof_handler,
        v,
        history,
        [&](const auto &, const auto &h) {
          point_means.assign(
            kf.n_points(),
            cell_pressure(kr, v, dt, h[0]->volume_offset, Kv, Dr, div_v));
          if (projected)
            projection.values(kf.fe_values(), point_means);
          for (unsigned int q = 0; q < kf.n_points(); ++q)
            update_point(kf.mapped_axis(q, dim - 1),
                         points.rate(q),
                         point_means[q],
                         points.map(q),
                         dt,
                         *h[q]);
        });
    }

    template <int dim>
    void HistoryUpdate<dim>::update_point(const Tensor<1, 3>          &normal,
                                          const SymmetricTensor<2, 3> &D,
                                          const double mean_stress,
                                          const material::Mandel6x6 *map,
                                          const double               dt,
                                          QuadraturePointHistory    &h) const
    {
      const auto r = material.evaluate(D, h.strain, dt, false, map);
      if (damage)
        {
          const auto d =
            damage->increment(r.deviatoric_stress,
                              mean_stress,
                              material::RigidViscoplastic::equivalent_stress(r),
                              dt * r.equivalent_strain_rate);
          h.oyane += d.oyane;
          h.cockcroft_latham += d.cockcroft_latham;
        }
      h.strain += dt * r.equivalent_strain_rate;
      h.strain_rate = r.equivalent_strain_rate;
      h.flow_stress =
        material.flow_stress().value(h.strain,
                                     std::max(r.equivalent_strain_rate,
                                              1e-300));
      h.mean_stress = mean_stress;
      // Through-thickness direction: the mapped last reference axis (the
      // layer direction of the sheet mesh), @p normal.
      h.thickness_strain += dt * (normal * (D * normal));
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
