#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
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


    namespace
    {
      /// Whether @p kept leaves out any cell (all ranks).
      template <int dim>
      bool trims(const state::State<dim>   &state,
                 const trimming::KeptCells *kept)
      {
        bool cut = false;
        if (kept)
          for (const auto &cell : state.tria.active_cell_iterators())
            if (cell->is_locally_owned() && !(*kept)[cell->active_cell_index()])
              cut = true;
        return Utilities::MPI::logical_or(cut, state.comm);
      }
    } // namespace

    template <int dim>
    Release<dim>::Release(const state::State<dim>           &state,
                          const Mapping<dim>                &configuration,
                          const material::RigidViscoplastic &material,
                          const material::ReleaseLaw        &law,
                          const VectorType                  *end_forces,
                          const trimming::KeptCells         *kept)
        : state(state)
        , mapping(configuration)
        , law(law)
        , prm(state.prm)
        , fe(FE_Q<dim>(release_degree(state)), dim)
        , part_fe(fe, FESystem<dim>(FE_Nothing<dim>(), dim))
        , quadrature(release_degree(state) + 1)
        , dh(state.tria)
        , part(state.tria)
        , kept(trims(state, kept) ? kept : nullptr)
        , end(state, configuration, material, law, quadrature)
        , end_forces(end_forces)
    {
      setup();
    }

    template <int dim>
    void Release<dim>::setup()
    {
      dh.distribute_dofs(fe);
      for (const auto &cell : part.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(in_part(cell) ? 0 : 1);
      part.distribute_dofs(part_fe);
      const IndexSet owned = part.locally_owned_dofs();
      IndexSet       relevant;
      DoFTools::extract_locally_relevant_dofs(part, relevant);
      supports = hold(state, mapping, part, constraints, prm.springback.slit);
      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(part, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 state.comm,
                                                 relevant);
      matrix.reinit(owned, owned, dsp, state.comm);
      u.reinit(owned, state.comm);
      residual.reinit(owned, state.comm);
      defect.reinit(owned, state.comm);
      part_ghost.reinit(owned, relevant, state.comm);
      IndexSet all_relevant;
      DoFTools::extract_locally_relevant_dofs(dh, all_relevant);
      u_full.reinit(dh.locally_owned_dofs(), state.comm);
      u_ghost.reinit(dh.locally_owned_dofs(), all_relevant, state.comm);
      for (auto *v : {&cell_residual, &cell_end, &cell_mean, &cell_yielded})
        v->reinit(state.tria.n_active_cells());
      for (auto &v : cell_stress)
        v.reinit(state.tria.n_active_cells());
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
      for (const auto &cell : part.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == 0)
          {
            k.reinit(cell);
            k.rates(part_ghost, eps);
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
            for (unsigned int i = 0; i < cell_stress.size(); ++i)
              cell_stress[i][c] = mean_stress.access_raw_entry(i) / cell_volume;
            cell_yielded[c] = cell_yield / cell_volume;
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
        if (cell->is_locally_owned() && in_part(cell))
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
    void Release<dim>::spread_displacement()
    {
      part_ghost                                 = u;
      const unsigned int                   n     = fe.n_dofs_per_cell();
      const IndexSet                       owned = dh.locally_owned_dofs();
      std::vector<types::global_dof_index> mine(n), dofs(n);
      u_full = 0;
      for (const auto &cell : part.active_cell_iterators())
        if (!cell->is_artificial() && cell->active_fe_index() == 0)
          {
            cell->get_dof_indices(mine);
            typename DoFHandler<dim>::active_cell_iterator(&state.tria,
                                                           cell->level(),
                                                           cell->index(),
                                                           &dh)
              ->get_dof_indices(dofs);
            for (unsigned int i = 0; i < n; ++i)
              if (owned.is_element(dofs[i]))
                u_full[dofs[i]] = part_ghost[mine[i]];
          }
      u_full.compress(VectorOperation::insert);
      u_ghost = u_full;
    }

    template <int dim>
    ReleaseSummary Release<dim>::solve()
    {
      ReleaseSummary s;
      s.supports         = describe_supports(supports, prm.geometry.model);
      u                  = 0;
      part_ghost         = u;
      defect             = 0;
      const double whole = assemble(true, s);
      // A trimmed part's load is its own end stress (eq. 13a).
      if (end_forces && !trimmed())
        {
          // g: the end stress's own imbalance in the release's space, no
          // load (eq. 12c): r(0) = the tools' forces.
          const VectorType f =
            load_on(part, constraints, state, mapping, *end_forces);
          defect = residual;
          defect -= f;
          s.imbalance = whole > 0 ? defect.l2_norm() / whole : 0;
          residual -= defect;
        }
      s.released_force = residual.l2_norm();
      measure_end_state(s);
      // One factorisation, in double precision: the forming's reuse and
      // single-precision settings serve its many similar solves, not this.
      parameters::LinearSolver settings = prm.linear;
      settings.factor_precision = parameters::FactorPrecision::double_precision;
      settings.reuse_iterations = 0;
      settings.low_rank_tolerance = 0;
      auto   linear = solver::create_linear_solver(settings, true);
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
          part_ghost = u;
          ++s.iterations;
          norm = assemble(false, s);
        }
      s.residual         = s.released_force > 0 ? norm / s.released_force : 0;
      s.max_displacement = u.linfty_norm();
      spread_displacement();
      return s;
    }

#define INSTANTIATE(dim)       \
  template class Release<dim>; \
  template unsigned int release_degree(const state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
