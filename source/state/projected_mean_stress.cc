#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/affine_constraints.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/state/projected_mean_stress.h>

namespace formsolve
{
  namespace state
  {
    using namespace dealii;

    template <int dim>
    void
    ProjectedMeanStress<dim>::project(const DoFHandler<dim>      &dof_handler,
                                      model::CellKinematics<dim> &k,
                                      const std::vector<double>  &cell_values,
                                      const VectorType           &layout)
    {
      const auto &fe    = dof_handler.get_fe();
      const auto  owned = dof_handler.locally_owned_dofs();
      IndexSet    relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      AffineConstraints<double> hanging(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, hanging);
      hanging.close();

      VectorType sums(owned, layout.get_mpi_communicator()),
        weights(owned, layout.get_mpi_communicator());
      const unsigned int                   n = fe.n_dofs_per_cell();
      Vector<double>                       local_sum(n), local_weight(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k.reinit(cell);
            local_weight = 0;
            for (unsigned int q = 0; q < k.n_points(); ++q)
              for (unsigned int i = 0; i < n; ++i)
                if (fe.system_to_component_index(i).first == 0)
                  local_weight[i] += k.fe_values().shape_value(i, q) * k.dV(q);
            local_sum = local_weight;
            local_sum *= cell_values[cell->active_cell_index()];
            cell->get_dof_indices(dofs);
            hanging.distribute_local_to_global(local_sum, dofs, sums);
            hanging.distribute_local_to_global(local_weight, dofs, weights);
          }
      sums.compress(VectorOperation::add);
      weights.compress(VectorOperation::add);
      for (const auto i : owned)
        sums[i] = weights[i] > 0 ? sums[i] / weights[i] : 0.;
      sums.compress(VectorOperation::insert);
      hanging.distribute(sums);
      field.reinit(layout, true);
      field = sums;
    }

    template <int dim>
    void ProjectedMeanStress<dim>::values(const FEValues<dim> &fv,
                                          std::vector<double> &out) const
    {
      out.resize(fv.n_quadrature_points);
      fv[FEValuesExtractors::Scalar(0)].get_function_values(field, out);
    }

#define INSTANTIATE(dim) template class ProjectedMeanStress<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
