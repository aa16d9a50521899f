#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <formsolve/model/current_mapping.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/vtu_writer.h>
#include <formsolve/springback/springback_output.h>

#include <algorithm>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    namespace
    {
      // In SymmetricTensor<2, 3>'s unrolled order; in 2-D the third axis
      // is the hoop direction (axisymmetric) or the section's normal y
      // (plane strain), and the components coupling it vanish.
      template <int dim>
      std::vector<std::string>
      residual_stress_names(const model::Kinematics<dim> &kinematics)
      {
        if (dim == 3)
          return {"residual_stress_xx",
                  "residual_stress_yy",
                  "residual_stress_zz",
                  "residual_stress_xy",
                  "residual_stress_xz",
                  "residual_stress_yz"};
        if (kinematics.axisymmetric())
          return {"residual_stress_rr",
                  "residual_stress_zz",
                  "residual_stress_hoop",
                  "residual_stress_rz"};
        return {"residual_stress_xx",
                "residual_stress_zz",
                "residual_stress_yy",
                "residual_stress_xz"};
      }
    } // namespace

    template <int dim>
    std::string write_sprung_part(const Release<dim>      &release,
                                  const state::State<dim> &state,
                                  const std::string       &directory)
    {
      const auto        &dh     = release.dof_handler();
      const unsigned int degree = dh.get_fe().degree;
      // The sprung mesh: the reference mapping plus the forming's
      // displacement (carried to the release's element) plus the
      // release's. (A cache on top of the current mapping, itself a cache,
      // would be asked for the support points of inactive cells.)
      VectorType forming(state.owned, state.relevant, state.comm);
      forming = state.displacement;
      VectorType total(release.owned_displacement());
      // With hanging nodes the interpolation needs the target's constraints.
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dh, relevant);
      AffineConstraints<double> hanging(relevant);
      DoFTools::make_hanging_node_constraints(dh, hanging);
      hanging.close();
      FETools::interpolate(state.dof_handler, forming, dh, hanging, total);
      total += release.owned_displacement();
      model::CurrentMapping<dim> sprung(
        std::max(degree, state.mapping->get_degree()));
      sprung.initialize(state.reference_mapping, dh, total, true);

      DataOut<dim> out;
      out.attach_dof_handler(dh);
      out.add_data_vector(
        release.displacement(),
        std::vector<std::string>(dim, "springback_displacement"),
        DataOut<dim>::type_dof_data,
        std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          dim,
          DataComponentInterpretation::component_is_part_of_vector));
      out.add_data_vector(release.residual_equivalent(),
                          "residual_equivalent_stress",
                          DataOut<dim>::type_cell_data);
      out.add_data_vector(release.residual_mean(),
                          "residual_mean_stress",
                          DataOut<dim>::type_cell_data);
      // The residual stress's components in the kinematics' frame, named
      // as a user reads them in the model's section.
      const auto names = residual_stress_names<dim>(state.kinematics);
      for (unsigned int k = 0; k < names.size(); ++k)
        out.add_data_vector(release.residual_stress(k),
                            names[k],
                            DataOut<dim>::type_cell_data);
      out.add_data_vector(release.end_equivalent(),
                          "end_equivalent_stress",
                          DataOut<dim>::type_cell_data);
      out.add_data_vector(release.yielded(),
                          "yielded_again",
                          DataOut<dim>::type_cell_data);
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      out.set_flags(flags);
      postprocess::select_cells<dim>(out, [&release](const auto &cell) {
        return release.in_part(cell);
      });
      out.build_patches(sprung, degree, DataOut<dim>::curved_inner_cells);
      return postprocess::write_vtu_atomically(out,
                                               directory,
                                               "springback",
                                               state.step,
                                               state.comm);
    }

    template <int dim>
    VectorType sprung_displacement(const Release<dim>      &release,
                                   const state::State<dim> &state)
    {
      AffineConstraints<double> hanging(state.relevant);
      DoFTools::make_hanging_node_constraints(state.dof_handler, hanging);
      hanging.close();
      VectorType u(state.owned, state.comm);
      FETools::interpolate(release.dof_handler(),
                           release.displacement(),
                           state.dof_handler,
                           hanging,
                           u);
      u += state.displacement;
      return u;
    }

#define INSTANTIATE(dim)                                            \
  template std::string write_sprung_part(const Release<dim> &,      \
                                         const state::State<dim> &, \
                                         const std::string &);      \
  template VectorType  sprung_displacement(const Release<dim> &,    \
                                           const state::State<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
