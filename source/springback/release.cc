#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/linear/linear_solver.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/parameters/require.h>
#include <formsolve/springback/release.h>


namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    template <int dim>
    unsigned int release_degree(const state::State<dim> &state)
    {
      const unsigned int d = state.prm.springback.degree;
      return d > 0 ? d : state.fe.degree;
    }


    template <int dim>
    Release<dim>::Release(const state::State<dim>           &state,
                          const Mapping<dim>                &configuration,
                          const material::RigidViscoplastic &material,
                          const material::ReleaseLaw        &law,
                          const VectorType                  *end_forces)
        : state(state)
        , mapping(configuration)
        , law(law)
        , prm(state.prm)
        , fe(FE_Q<dim>(release_degree(state)), dim)
        , quadrature(release_degree(state) + 1)
        , dh(state.tria)
        , end(state, configuration, material, law, quadrature)
        , end_forces(end_forces)
    {
      setup();
    }

    template <int dim>
    void Release<dim>::setup()
    {
      dh.distribute_dofs(fe);
      const IndexSet owned = dh.locally_owned_dofs();
      IndexSet       relevant;
      DoFTools::extract_locally_relevant_dofs(dh, relevant);
      supports = hold(state, mapping, dh, constraints);

      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dh, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 state.comm,
                                                 relevant);
      matrix.reinit(owned, owned, dsp, state.comm);
      u.reinit(owned, state.comm);
      residual.reinit(owned, state.comm);
      defect.reinit(owned, state.comm);
      u_ghost.reinit(owned, relevant, state.comm);
      for (auto *v : {&cell_residual, &cell_end, &cell_mean, &cell_yielded})
        v->reinit(state.tria.n_active_cells());
    }

    template <int dim>
    double Release<dim>::assemble(const bool with_matrix, ReleaseSummary &s)
    {
      model::CellKinematics<dim> k(state.kinematics, mapping, fe, quadrature);
      const unsigned int         n = fe.n_dofs_per_cell();
      FullMatrix<double>         K(n, n);
      Vector<double>             r(n);
      std::vector<types::global_dof_index> dofs(n);
      std::vector<SymmetricTensor<2, 3>>   eps;
      std::vector<model::ShapeStrain>      B;
      std::vector<SymmetricTensor<2, 3>>   CB(n);
      if (with_matrix)
        matrix = 0;
      residual       = 0;
      double yielded = 0, volume = 0, max_ratio = 0, max_plastic = 0;
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k.reinit(cell);
            k.rates(u_ghost, eps);
            const auto &points = end.at(cell);
            K                  = 0;
            r                  = 0;
            SymmetricTensor<2, 3> mean_stress;
            double cell_volume = 0, cell_yield = 0, eq = 0, eq_end = 0;
            for (unsigned int q = 0; q < k.n_points(); ++q)
              {
                const auto &p = points[q];
                const auto  sr =
                  law.respond(p.stress, eps[q], p.strain, p.metric);
                const double dV = k.dV(q);
                k.shape_strains(q, B);
                for (unsigned int i = 0; i < n; ++i)
                  r(i) += B[i].contract(sr.stress) * dV;
                if (with_matrix)
                  {
                    for (unsigned int j = 0; j < n; ++j)
                      CB[j] = sr.tangent * B[j].tensor();
                    for (unsigned int i = 0; i < n; ++i)
                      for (unsigned int j = 0; j < n; ++j)
                        K(i, j) += B[i].contract(CB[j]) * dV;
                  }
                cell_volume += dV;
                mean_stress += sr.stress * dV;
                eq += law.equivalent(sr.stress, p.metric) * dV;
                eq_end += law.equivalent(p.stress, p.metric) * dV;
                cell_yield += sr.yielded ? dV : 0;
                max_ratio   = std::max(max_ratio, sr.trial_ratio);
                max_plastic = std::max(max_plastic, sr.plastic_strain);
              }
            const unsigned int c = cell->active_cell_index();
            cell_residual[c]     = eq / cell_volume;
            cell_end[c]          = eq_end / cell_volume;
            cell_mean[c]         = trace(mean_stress) / (3 * cell_volume);
            cell_yielded[c]      = cell_yield / cell_volume;
            yielded += cell_yield;
            volume += cell_volume;
            cell->get_dof_indices(dofs);
            if (with_matrix)
              constraints.distribute_local_to_global(K,
                                                     r,
                                                     dofs,
                                                     matrix,
                                                     residual);
            else
              constraints.distribute_local_to_global(r, dofs, residual);
          }
      if (with_matrix)
        matrix.compress(VectorOperation::add);
      residual.compress(VectorOperation::add);
      residual -= defect;
      s.volume           = Utilities::MPI::sum(volume, state.comm);
      s.yielded_fraction = Utilities::MPI::sum(yielded, state.comm) / s.volume;
      s.max_trial_ratio  = Utilities::MPI::max(max_ratio, state.comm);
      s.max_plastic_strain = Utilities::MPI::max(max_plastic, state.comm);
      return residual.l2_norm();
    }

    template <int dim>
    void Release<dim>::measure_end_state(ReleaseSummary &s) const
    {
      model::CellKinematics<dim> k(state.kinematics, mapping, fe, quadrature);
      const double cutoff = 10 * prm.material.limiting_strain_rate;
      double       small = 0, rigid = 0;
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k.reinit(cell);
            const auto &points = end.at(cell);
            for (unsigned int q = 0; q < k.n_points(); ++q)
              {
                const double yield_strain =
                  law.yield_stress(points[q].strain) / law.young_modulus();
                if (points[q].strain <
                    prm.springback.sound_strain_ratio * yield_strain)
                  small += k.dV(q);
                if (points[q].rate < cutoff)
                  rigid += k.dV(q);
              }
          }
      s.small_strain_fraction =
        Utilities::MPI::sum(small, state.comm) / s.volume;
      s.rigid_fraction = Utilities::MPI::sum(rigid, state.comm) / s.volume;
    }

    template <int dim>
    VectorType Release<dim>::tool_forces(const VectorType &f) const
    {
      // The same cell on the forming's DoFHandler.
      const auto forming = [this](const auto &cell) {
        return
          typename DoFHandler<dim>::active_cell_iterator(&state.tria,
                                                         cell->level(),
                                                         cell->index(),
                                                         &state.dof_handler);
      };
      VectorType out(u);
      out                   = 0;
      const unsigned int n1 = state.fe.n_dofs_per_cell(),
                         n2 = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs1(n1), dofs2(n2);
      VectorType f1(state.owned, state.relevant, state.comm);
      f1 = f;
      if (state.fe.degree == fe.degree)
        {
          // The same element: the same local DoFs.
          const auto owned = dh.locally_owned_dofs();
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                forming(cell)->get_dof_indices(dofs1);
                cell->get_dof_indices(dofs2);
                for (unsigned int i = 0; i < n2; ++i)
                  if (owned.is_element(dofs2[i]))
                    out[dofs2[i]] = f1[dofs1[i]];
              }
          out.compress(VectorOperation::insert);
          constraints.set_zero(out);
          return out;
        }
      // Otherwise the forces become a density t = f / m (m: the forming
      // element's lumped volume per DoF) whose work against the release's
      // shape functions is the load: the resultant is kept, and no force
      // is a point load on the release's finer element (eq. 12c).
      model::CellKinematics<dim> k1(state.kinematics,
                                    mapping,
                                    state.fe,
                                    quadrature,
                                    update_values);
      model::CellKinematics<dim> k2(state.kinematics,
                                    mapping,
                                    fe,
                                    quadrature,
                                    update_values);
      VectorType                 mass(state.owned, state.comm);
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k1.reinit(cell);
            cell->get_dof_indices(dofs1);
            Vector<double> m(n1);
            for (unsigned int q = 0; q < k1.n_points(); ++q)
              for (unsigned int i = 0; i < n1; ++i)
                m(i) += k1.fe_values().shape_value(i, q) * k1.dV(q);
            state.constraints.distribute_local_to_global(m, dofs1, mass);
          }
      mass.compress(VectorOperation::add);
      VectorType density(state.owned, state.comm);
      for (const auto i : state.owned)
        density[i] = mass[i] > 0 ? f[i] / mass[i] : 0.;
      density.compress(VectorOperation::insert);
      state.constraints.distribute(density);
      f1 = density;
      Vector<double> r(n2);
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto from = forming(cell);
            k1.reinit(from);
            k2.reinit(cell);
            from->get_dof_indices(dofs1);
            cell->get_dof_indices(dofs2);
            r = 0;
            for (unsigned int q = 0; q < k2.n_points(); ++q)
              {
                Tensor<1, dim> t;
                for (unsigned int i = 0; i < n1; ++i)
                  t[state.fe.system_to_component_index(i).first] +=
                    f1[dofs1[i]] * k1.fe_values().shape_value(i, q);
                for (unsigned int j = 0; j < n2; ++j)
                  r(j) += t[fe.system_to_component_index(j).first] *
                          k2.fe_values().shape_value(j, q) * k2.dV(q);
              }
            constraints.distribute_local_to_global(r, dofs2, out);
          }
      out.compress(VectorOperation::add);
      return out;
    }

    template <int dim>
    ReleaseSummary Release<dim>::solve()
    {
      ReleaseSummary s;
      s.supports         = describe_supports(supports, prm.geometry.model);
      u                  = 0;
      u_ghost            = u;
      defect             = 0;
      const double whole = assemble(true, s);
      if (end_forces)
        {
          // g = int B^T sigma_end dV - the tools' forces; r(0) = those.
          defect = residual;
          defect -= tool_forces(*end_forces);
          s.imbalance = whole > 0 ? defect.l2_norm() / whole : 0;
          residual -= defect;
        }
      s.released_force = residual.l2_norm();
      measure_end_state(s);
      auto   linear = solver::create_linear_solver(prm.linear, true);
      double norm   = s.released_force;
      // A part without stress has nothing to release: u = 0 exactly.
      while (norm > prm.springback.tolerance * s.released_force)
        {
          AssertThrow(s.iterations < prm.springback.max_iterations,
                      ExcMessage("springback: the release did not converge "
                                 "in Springback/Maximum iterations = " +
                                 std::to_string(prm.springback.max_iterations) +
                                 " (|r|/|f| = " +
                                 std::to_string(norm / s.released_force) +
                                 ")"));
          if (s.iterations > 0)
            assemble(true, s);
          VectorType du(u), rhs(residual);
          rhs *= -1.;
          linear->solve(matrix, du, rhs, false);
          constraints.distribute(du);
          u += du;
          u_ghost = u;
          ++s.iterations;
          norm = assemble(false, s);
        }
      s.residual         = s.released_force > 0 ? norm / s.released_force : 0;
      s.max_displacement = u.linfty_norm();
      return s;
    }

#define INSTANTIATE(dim)       \
  template class Release<dim>; \
  template unsigned int release_degree(const state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
