#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/springback/end_state.h>
#include <formsolve/state/cell_points.h>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    template <int dim>
    EndState<dim>::EndState(const state::State<dim>           &state,
                            const Mapping<dim>                &mapping,
                            const material::RigidViscoplastic &material,
                            const material::ReleaseLaw        &law,
                            const Quadrature<dim>             &quadrature)
        : points(state.tria.n_active_cells())
    {
      // From the values at the history points to those at the release's:
      // the polynomial of the forming's degree they interpolate.
      const FE_DGQ<dim>  local(state.fe.degree);
      FullMatrix<double> project(local.n_dofs_per_cell(),
                                 state.history_rule.size()),
        evaluate(quadrature.size(), local.n_dofs_per_cell());
      FETools::compute_projection_from_quadrature_points_matrix(
        local,
        state.history_rule,
        state.history_rule,
        project);
      FETools::compute_interpolation_to_quadrature_points_matrix(local,
                                                                 quadrature,
                                                                 evaluate);
      FullMatrix<double> carry(quadrature.size(), state.history_rule.size());
      evaluate.mmult(carry, project);

      state::CellPoints<dim> cp(material,
                                state.kinematics,
                                mapping,
                                state.reference_mapping,
                                state.fe,
                                quadrature,
                                quadrature,
                                update_default);
      const unsigned int     n = quadrature.size();
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cp.reinit(cell, state.velocity_ghost);
            const auto h = state.history.get_data(cell);
            auto      &p = points[cell->active_cell_index()];
            p.resize(n);
            for (unsigned int q = 0; q < n; ++q)
              {
                double strain = 0, mean = 0;
                for (unsigned int k = 0; k < h.size(); ++k)
                  {
                    strain += carry(q, k) * h[k]->strain;
                    mean += carry(q, k) * h[k]->mean_stress;
                  }
                p[q].strain  = std::max(strain, 0.);
                const auto r = material.evaluate(cp.rate(q),
                                                 p[q].strain,
                                                 0,
                                                 false,
                                                 cp.map(q));
                p[q].stress =
                  r.deviatoric_stress + mean * unit_symmetric_tensor<3>();
                p[q].rate   = r.equivalent_strain_rate;
                p[q].metric = law.metric(cp.axes(q));
              }
          }
    }

#define INSTANTIATE(dim) template class EndState<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
