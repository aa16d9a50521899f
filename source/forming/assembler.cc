#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/forming/cell_scatter.h>
#include <formsolve/forming/cell_tangent.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/state/cell_points.h>
#include <formsolve/state/volumetric_rate.h>

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
      /// The cell's K and r into the system: K by position where @p scatter
      /// maps the cell, else condensed with the constraints as r is.
      template <int dim>
      void add_cell(const unsigned int                          index,
                    const FullMatrix<double>                   &K,
                    const Vector<double>                       &r,
                    const std::vector<types::global_dof_index> &dofs,
                    const AffineConstraints<double>            &constraints,
                    MatrixType                                 *matrix,
                    VectorType                                 &residual,
                    const CellScatter<dim>                     *scatter)
      {
        if (matrix && scatter && scatter->maps(index))
          {
            scatter->add(index, K, *matrix);
            constraints.distribute_local_to_global(r, dofs, residual);
          }
        else if (matrix)
          constraints.distribute_local_to_global(K, r, dofs, *matrix, residual);
        else
          constraints.distribute_local_to_global(r, dofs, residual);
      }
      /// One point's deviatoric residual and (with @p form 1: the product
      /// form, 2: the general one; 0: none) its tangent; @p map: Hill's map
      /// at the point, or nullptr.
      template <int dim>
      void add_point(const material::RigidViscoplastic &material,
                     const material::PointResponse     &m,
                     const SymmetricTensor<2, 3>       &w_rate,
                     const bool                         dual,
                     const material::Mandel6x6         *map,
                     const unsigned int                 q,
                     const double                       dV,
                     const std::vector<ShapeStrain>    &B,
                     const unsigned int                 form,
                     CellTangent<dim>                  &tangent,
                     Vector<double>                    &r,
                     std::vector<double>               &s,
                     std::vector<double>               &u)
      {
        // d s'/dD = 2 mu P_dev + beta D' (x) D'  (doc/theory.md, eq. 4,
        // 4b): s = B : D', u = beta_h/2 s + beta_p t with t = B : w.
        const double mu     = m.viscosity * dV;
        const double beta_h = (m.beta - m.beta_plastic) * dV;
        const double beta_p = 0.5 * m.beta_plastic * dV;
        for (unsigned int i = 0; i < B.size(); ++i)
          {
            r[i] += B[i].contract(m.deviatoric_stress) * dV;
            if (form == 1)
              {
                s[i] = B[i].contract(m.strain_rate_deviator);
                u[i] = 0.5 * beta_h * s[i] +
                       beta_p * (dual ? B[i].contract(w_rate) : s[i]);
              }
          }
        if (form == 1)
          tangent.add_deviatoric(q, B, mu, s, u);
        else if (form == 2 && map)
          tangent.add_general(q, B, material.tangent(m, w_rate, *map), dV);
        else if (form == 2)
          tangent.add_general(q, B, material.tangent(m, w_rate) * dV);
      }

      /// Stress-velocity linearisation: (4/9) s/rate^3 D'(x)D' becomes its
      /// symmetric part with one D' replaced by rate w, w the trial dual
      /// direction of the point.
      template <typename CellIterator>
      SymmetricTensor<2, 3>
      dual_rate(DualStress                        &dual,
                const material::RigidViscoplastic &material,
                const material::PointResponse     &m,
                const CellIterator                &cell,
                const unsigned int                 q)
      {
        dual.trial_metric(cell->active_cell_index(), q, m.metric);
        return dual.trial(cell->active_cell_index(),
                          q,
                          m.strain_rate_deviator,
                          material.cutoff_rate(),
                          material.smooth_rigid_zone()) *
               m.dual_rate;
      }

      /// Incompressibility by penalty at the reduced points (reduced
      /// integration against locking): r_i += K_v div(v) tr(B_i) dV, and its
      /// tangent if @p with_tangent.
      template <int dim>
      void add_volumetric(const CellKinematics<dim> &kr,
                          const std::vector<double> &div_v,
                          const double               Kv,
                          const bool                 with_tangent,
                          std::vector<ShapeStrain>  &B,
                          std::vector<double>       &tr,
                          CellTangent<dim>          &tangent,
                          Vector<double>            &r)
      {
        for (unsigned int q = 0; q < kr.n_points(); ++q)
          {
            const double dV = kr.dV(q);
            kr.shape_strains(q, B);
            for (unsigned int i = 0; i < B.size(); ++i)
              {
                tr[i] = B[i].trace();
                r[i] += Kv * div_v[q] * tr[i] * dV;
              }
            if (with_tangent)
              tangent.add_volumetric(q, tr, Kv * dV);
          }
      }
    } // namespace

    template <int dim>
    Assembler<dim>::Assembler(const material::RigidViscoplastic &material,
                              const model::Kinematics<dim>      &kinematics,
                              const Mapping<dim> &reference_mapping,
                              const unsigned int  degree)
        : material(material)
        , kinematics(kinematics)
        , reference_mapping(reference_mapping)
        , full(degree + 1)
        , reduced(degree)
        , product_form(material.isotropic())
    {}

    template <int dim>
    double Assembler<dim>::assemble_body(
      const DoFHandler<dim>            &dof_handler,
      const Mapping<dim>               &mapping,
      const AffineConstraints<double>  &constraints,
      const VectorType                 &v,
      const HistoryStorage<dim>        &history,
      const double                      dt,
      const bool                        newton,
      MatrixType                       *matrix,
      VectorType                       &residual,
      DualStress                       *dual,
      const CellScatter<dim>           *scatter,
      const material::PointFrames<dim> *frames) const
    {
      const auto            &fe = dof_handler.get_fe();
      const unsigned int     n  = fe.n_dofs_per_cell();
      state::CellPoints<dim> points(material,
                                    kinematics,
                                    mapping,
                                    reference_mapping,
                                    fe,
                                    full,
                                    reduced,
                                    update_default,
                                    frames);
      CellKinematics<dim>   &kf = points.full();
      CellKinematics<dim>   &kr = points.reduced();

      CellTangent<dim>                     tangent(fe,
                               kf.n_points(),
                               kr.n_points(),
                               kinematics.axisymmetric());
      FullMatrix<double>                   K(n, n);
      Vector<double>                       r(n);
      std::vector<SymmetricTensor<2, 3>>   Dr;
      std::vector<ShapeStrain>             B;
      std::vector<double>                  tr(n), s(n), u(n), div_v;
      std::vector<types::global_dof_index> dofs(n);
      const double                         Kv     = material.bulk_viscosity();
      double                               f_int2 = 0;

      if (matrix)
        *matrix = 0;
      residual = 0;

      points.for_each_owned(
        dof_handler,
        v,
        history,
        [&](const auto &cell, const auto &h) {
          r = 0;
          for (unsigned int q = 0; q < kf.n_points(); ++q)
            {
              const auto m =
                material.evaluate(points.rate(q),
                                  h[q]->strain,
                                  dt,
                                  newton,
                                  points.map(q),
                                  dual
                                    ? dual->start(cell->active_cell_index(), q)
                                    : nullptr);
              const double dV = kf.dV(q);
              kf.shape_strains(q, B);
              add_point(material,
                        m,
                        dual ? dual_rate(*dual, material, m, cell, q)
                             : m.strain_rate_deviator,
                        dual != nullptr,
                        points.map(q),
                        q,
                        dV,
                        B,
                        matrix ? (product_form ? 1 : 2) : 0,
                        tangent,
                        r,
                        s,
                        u);
            }
          state::volumetric_rates(kr, v, dt, h[0]->volume_offset, Dr, div_v);
          add_volumetric(kr, div_v, Kv, matrix != nullptr, B, tr, tangent, r);
          if (matrix)
            tangent.finish(K);
          f_int2 += r.norm_sqr();
          cell->get_dof_indices(dofs);
          add_cell(cell->active_cell_index(),
                   K,
                   r,
                   dofs,
                   constraints,
                   matrix,
                   residual,
                   scatter);
        });

      if (matrix)
        matrix->compress(VectorOperation::add);
      residual.compress(VectorOperation::add);
      return std::sqrt(Utilities::MPI::sum(
        f_int2,
        dof_handler.get_triangulation().get_communicator()));
    }

#define INSTANTIATE(dim) template class Assembler<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
