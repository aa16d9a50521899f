#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/contact/contact_law.h>
#include <formsolve/solver/assembler.h>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    Assembler<dim>::Assembler(const material::RigidViscoplastic<dim> &material,
                              const Mapping<dim> &reference_mapping,
                              const unsigned int  degree)
        : material(material)
        , reference_mapping(reference_mapping)
        , full(degree + 1)
        , reduced(degree)
    {}

    template <int dim>
    template <typename Iterator>
    void Assembler<dim>::volumetric_rates(const Iterator      &cell,
                                          FEValues<dim>       &current,
                                          FEValues<dim>       &initial,
                                          const VectorType    &v,
                                          const double         dt,
                                          std::vector<double> &rates) const
    {
      const FEValuesExtractors::Vector velocity(0);
      initial.reinit(cell);
      current[velocity].get_function_divergences(v, rates);
      if (dt > 0)
        for (unsigned int q = 0; q < rates.size(); ++q)
          rates[q] += std::log(current.JxW(q) / initial.JxW(q)) / dt;
    }

    template <int dim>
    double
    Assembler<dim>::assemble(const DoFHandler<dim>           &dof_handler,
                             const Mapping<dim>              &mapping,
                             const AffineConstraints<double> &constraints,
                             const VectorType                &v,
                             const HistoryStorage<dim>       &history,
                             const double                     dt,
                             const ContactInput<dim>         &contact,
                             const bool                       newton,
                             MatrixType                      *matrix,
                             VectorType                      &residual) const
    {
      const double f_int = assemble_body(dof_handler,
                                         mapping,
                                         constraints,
                                         v,
                                         history,
                                         dt,
                                         newton,
                                         matrix,
                                         residual);
      add_contact(constraints, dt, contact, newton, matrix, residual);
      return f_int;
    }

    template <int dim>
    void
    Assembler<dim>::add_contact(const AffineConstraints<double> &constraints,
                                const double                     dt,
                                const ContactInput<dim>         &contact,
                                const bool                       newton,
                                MatrixType                      *matrix,
                                VectorType                      &residual) const
    {
      if (contact.set != nullptr)
        {
          FullMatrix<double>                   Kc(dim, dim);
          Vector<double>                       rc(dim);
          std::vector<types::global_dof_index> node_dofs(dim);
          const auto                          &set = *contact.set;
          for (unsigned int k = 0; k < set.pairs.size(); ++k)
            {
              const auto &pair = set.pairs[k];
              if (!pair.active)
                continue;
              const auto f = contact::penalty_friction_force(
                pair,
                (*contact.epsilon)[k],
                contact.tools->friction_coefficient(pair.tool),
                contact.regularisation_velocity,
                dt,
                newton);
              for (unsigned int a = 0; a < dim; ++a)
                {
                  node_dofs[a] = set.nodes[pair.node].dofs[a];
                  rc[a]        = -f.force[a];
                  for (unsigned int b = 0; b < dim; ++b)
                    Kc(a, b) = f.stiffness[a][b];
                }
              if (matrix)
                constraints.distribute_local_to_global(Kc,
                                                       rc,
                                                       node_dofs,
                                                       *matrix,
                                                       residual);
              else
                constraints.distribute_local_to_global(rc, node_dofs, residual);
            }
        }

      if (matrix)
        matrix->compress(VectorOperation::add);
      residual.compress(VectorOperation::add);
    }

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
                                  VectorType &residual) const
    {
      const auto        &fe = dof_handler.get_fe();
      const unsigned int n  = fe.n_dofs_per_cell();
      FEValues<dim> fv(mapping, fe, full, update_gradients | update_JxW_values);
      FEValues<dim> fr(mapping,
                       fe,
                       reduced,
                       update_gradients | update_JxW_values);
      FEValues<dim> f0(reference_mapping, fe, reduced, update_JxW_values);
      const FEValuesExtractors::Vector velocity(0);

      FullMatrix<double>                   K(n, n);
      Vector<double>                       r(n);
      std::vector<SymmetricTensor<2, dim>> D(full.size());
      std::vector<Tensor<1, dim>>          g(n);
      std::vector<unsigned int>            comp(n);
      std::vector<double> tr(n), s(n), div(n), div_v(reduced.size());
      std::vector<types::global_dof_index> dofs(n);
      const double                         Kv     = material.bulk_viscosity();
      double                               f_int2 = 0;
      for (unsigned int i = 0; i < n; ++i)
        comp[i] = fe.system_to_component_index(i).first;

      if (matrix)
        *matrix = 0;
      residual = 0;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            fr.reinit(cell);
            K = 0;
            r = 0;
            fv[velocity].get_function_symmetric_gradients(v, D);
            const auto h = history.get_data(cell);
            for (unsigned int q = 0; q < full.size(); ++q)
              {
                const auto m =
                  material.evaluate(D[q], h[q]->strain, dt, newton);
                const double JxW = fv.JxW(q);
                // Shape function i has one component c_i and gradient g_i, so
                // B_i = sym(e_c (x) g_i): B_i:B_j, tr B_i and D':B_i reduce to
                // products of vector entries.
                for (unsigned int i = 0; i < n; ++i)
                  {
                    g[i]       = fv.shape_grad(i, q);
                    tr[i]      = g[i][comp[i]];
                    double sig = 0, dev = 0;
                    for (unsigned int k = 0; k < dim; ++k)
                      {
                        sig += m.deviatoric_stress[comp[i]][k] * g[i][k];
                        dev += m.strain_rate_deviator[comp[i]][k] * g[i][k];
                      }
                    s[i] = dev;
                    r[i] += sig * JxW;
                  }
                if (matrix)
                  {
                    // d s'/dD = 2 mu P_dev + beta D' (x) D'  (doc/theory.md,
                    // eq. 4)
                    const double mu = m.viscosity * JxW, beta = m.beta * JxW;
                    for (unsigned int i = 0; i < n; ++i)
                      for (unsigned int j = 0; j <= i; ++j)
                        {
                          const double BB =
                            0.5 * ((comp[i] == comp[j] ? g[i] * g[j] : 0.) +
                                   g[i][comp[j]] * g[j][comp[i]]);
                          K(i, j) += 2. * mu * (BB - tr[i] * tr[j] / 3.) +
                                     beta * s[i] * s[j];
                        }
                  }
              }
            // Incompressibility by penalty, reduced integration against
            // locking.
            volumetric_rates(cell, fr, f0, v, dt, div_v);
            for (unsigned int q = 0; q < reduced.size(); ++q)
              {
                const double JxW = fr.JxW(q);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    div[i] = fr.shape_grad(i, q)[comp[i]];
                    r[i] += Kv * div_v[q] * div[i] * JxW;
                  }
                if (matrix)
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j <= i; ++j)
                      K(i, j) += Kv * div[i] * div[j] * JxW;
              }
            if (matrix)
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = i + 1; j < n; ++j)
                  K(i, j) = K(j, i);
            f_int2 += r.norm_sqr();
            cell->get_dof_indices(dofs);
            if (matrix)
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
      const auto   &fe = dof_handler.get_fe();
      FEValues<dim> fv(mapping, fe, full, update_gradients | update_jacobians);
      FEValues<dim> fr(mapping,
                       fe,
                       reduced,
                       update_gradients | update_JxW_values);
      FEValues<dim> f0(reference_mapping, fe, reduced, update_JxW_values);
      const FEValuesExtractors::Vector     velocity(0);
      std::vector<SymmetricTensor<2, dim>> D(full.size());
      std::vector<double>                  div_v(reduced.size());
      const double                         Kv   = material.bulk_viscosity();
      const auto                          &flow = material.flow_stress();

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            fr.reinit(cell);
            fv[velocity].get_function_symmetric_gradients(v, D);
            volumetric_rates(cell, fr, f0, v, dt, div_v);
            double mean_div = 0, volume = 0;
            for (unsigned int q = 0; q < reduced.size(); ++q)
              {
                mean_div += div_v[q] * fr.JxW(q);
                volume += fr.JxW(q);
              }
            const double mean_stress = Kv * mean_div / volume;

            auto h = history.get_data(cell);
            for (unsigned int q = 0; q < full.size(); ++q)
              {
                const auto r = material.evaluate(D[q], h[q]->strain, dt, false);
                h[q]->strain += dt * r.equivalent_strain_rate;
                h[q]->strain_rate = r.equivalent_strain_rate;
                h[q]->flow_stress =
                  flow.value(h[q]->strain,
                             std::max(r.equivalent_strain_rate, 1e-300));
                h[q]->mean_stress = mean_stress;
                // Through-thickness direction: the mapped third reference axis
                // (the extrusion direction of the sheet mesh).
                Tensor<1, dim> t;
                for (unsigned int d = 0; d < dim; ++d)
                  t[d] = fv.jacobian(q)[d][dim - 1];
                t /= t.norm();
                h[q]->thickness_strain += dt * (t * (D[q] * t));
              }
          }
    }

    template <int dim>
    double Assembler<dim>::integrate(const DoFHandler<dim>     &dof_handler,
                                     const Mapping<dim>        &mapping,
                                     const HistoryStorage<dim> *history) const
    {
      FEValues<dim> fv(mapping, dof_handler.get_fe(), full, update_JxW_values);
      double        sum = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            for (unsigned int q = 0; q < full.size(); ++q)
              sum +=
                (history ? history->get_data(cell)[q]->strain : 1.) * fv.JxW(q);
          }
      return Utilities::MPI::sum(
        sum,
        dof_handler.get_triangulation().get_communicator());
    }

    template <int dim>
    double Assembler<dim>::volume(const DoFHandler<dim> &dof_handler,
                                  const Mapping<dim>    &mapping) const
    {
      return integrate(dof_handler, mapping, nullptr);
    }

    template <int dim>
    double
    Assembler<dim>::strain_integral(const DoFHandler<dim>     &dof_handler,
                                    const Mapping<dim>        &mapping,
                                    const HistoryStorage<dim> &history) const
    {
      return integrate(dof_handler, mapping, &history);
    }

    template <int dim>
    double Assembler<dim>::internal_power(const DoFHandler<dim> &dof_handler,
                                          const Mapping<dim>    &mapping,
                                          const VectorType      &v,
                                          const HistoryStorage<dim> &history,
                                          const double               dt) const
    {
      const auto   &fe = dof_handler.get_fe();
      FEValues<dim> fv(mapping, fe, full, update_gradients | update_JxW_values);
      FEValues<dim> fr(mapping,
                       fe,
                       reduced,
                       update_gradients | update_JxW_values);
      const FEValuesExtractors::Vector     velocity(0);
      std::vector<SymmetricTensor<2, dim>> D(full.size());
      std::vector<double>                  div_v(reduced.size());
      double                               power = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            fr.reinit(cell);
            fv[velocity].get_function_symmetric_gradients(v, D);
            fr[velocity].get_function_divergences(v, div_v);
            const auto h = history.get_data(cell);
            for (unsigned int q = 0; q < full.size(); ++q)
              power += material.evaluate(D[q], h[q]->strain, dt, false)
                         .deviatoric_stress *
                       D[q] * fv.JxW(q);
            for (unsigned int q = 0; q < reduced.size(); ++q)
              power +=
                material.bulk_viscosity() * div_v[q] * div_v[q] * fr.JxW(q);
          }
      return Utilities::MPI::sum(
        power,
        dof_handler.get_triangulation().get_communicator());
    }

    template class Assembler<3>;
  } // namespace solver
} // namespace formsolve
