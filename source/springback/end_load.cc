#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>

#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/springback/end_load.h>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    namespace
    {
      /// The same cell on @p state's DoFHandler.
      template <int dim>
      typename DoFHandler<dim>::active_cell_iterator
      forming(const state::State<dim>                              &state,
              const typename DoFHandler<dim>::active_cell_iterator &cell)
      {
        return
          typename DoFHandler<dim>::active_cell_iterator(&state.tria,
                                                         cell->level(),
                                                         cell->index(),
                                                         &state.dof_handler);
      }
    } // namespace

    template <int dim>
    VectorType force_density(const state::State<dim> &state,
                             const Mapping<dim>      &mapping,
                             const VectorType        &f)
    {
      model::CellKinematics<dim>           k(state.kinematics,
                                   mapping,
                                   state.fe,
                                   QGauss<dim>(state.fe.degree + 1),
                                   update_values);
      const unsigned int                   n = state.fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      VectorType                           mass(state.owned, state.comm);
      Vector<double>                       m(n);
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            k.reinit(cell);
            cell->get_dof_indices(dofs);
            m = 0;
            for (unsigned int q = 0; q < k.n_points(); ++q)
              for (unsigned int i = 0; i < n; ++i)
                m(i) += k.fe_values().shape_value(i, q) * k.dV(q);
            state.constraints.distribute_local_to_global(m, dofs, mass);
          }
      mass.compress(VectorOperation::add);
      VectorType density(state.owned, state.comm);
      for (const auto i : state.owned)
        density[i] = mass[i] > 0 ? f[i] / mass[i] : 0.;
      density.compress(VectorOperation::insert);
      state.constraints.distribute(density);
      VectorType ghosted(state.owned, state.relevant, state.comm);
      ghosted = density;
      return ghosted;
    }

    template <int dim>
    VectorType load_on(const DoFHandler<dim>           &dh,
                       const AffineConstraints<double> &constraints,
                       const state::State<dim>         &state,
                       const Mapping<dim>              &mapping,
                       const VectorType                &f)
    {
      const auto        &fe    = dh.get_fe();
      const IndexSet     owned = dh.locally_owned_dofs();
      VectorType         out(owned, dh.get_communicator());
      const unsigned int n1 = state.fe.n_dofs_per_cell(),
                         n2 = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs1(n1), dofs2(n2);
      if (state.fe.degree == fe.degree)
        {
          // The same element: the same local DoFs.
          VectorType f1(state.owned, state.relevant, state.comm);
          f1 = f;
          for (const auto &cell : dh.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                forming(state, cell)->get_dof_indices(dofs1);
                cell->get_dof_indices(dofs2);
                for (unsigned int i = 0; i < n2; ++i)
                  if (owned.is_element(dofs2[i]))
                    out[dofs2[i]] = f1[dofs1[i]];
              }
          out.compress(VectorOperation::insert);
          constraints.set_zero(out);
          return out;
        }
      // Otherwise the density's work against dh's shape functions: the
      // resultant is kept, and no force is a point load on a finer element.
      const VectorType           density = force_density(state, mapping, f);
      const QGauss<dim>          quadrature(fe.degree + 1);
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
      Vector<double>             r(n2);
      for (const auto &cell : dh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto from = forming(state, cell);
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
                    density[dofs1[i]] * k1.fe_values().shape_value(i, q);
                for (unsigned int j = 0; j < n2; ++j)
                  r(j) += t[fe.system_to_component_index(j).first] *
                          k2.fe_values().shape_value(j, q) * k2.dV(q);
              }
            constraints.distribute_local_to_global(r, dofs2, out);
          }
      out.compress(VectorOperation::add);
      return out;
    }

#define INSTANTIATE(dim)                                         \
  template VectorType force_density(const state::State<dim> &,   \
                                    const Mapping<dim> &,        \
                                    const VectorType &);         \
  template VectorType load_on(const DoFHandler<dim> &,           \
                              const AffineConstraints<double> &, \
                              const state::State<dim> &,         \
                              const Mapping<dim> &,              \
                              const VectorType &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
