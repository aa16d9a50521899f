// The sheet measurements under prescribed homogeneous stretching, where the
// answers are exact: plane strain (x stretched by e^eps, z by e^-eps) gives
// thickness t0 e^-eps and (minor, major) = (0, eps); equibiaxial stretching
// (x, y or r by e^eps, z by e^-2eps) gives t0 e^-2eps and (eps, eps), in the
// quarter 3-D and in the axisymmetric model.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/postprocess/sheet_measures.h>

#include "check.h"
#include "small_blank.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  template <int dim>
  void check(const std::string    &name,
             const model::Model    m,
             const Tensor<1, dim> &log_stretch, // per axis, last = thickness
             const double          major,
             const double          minor)
  {
    test::SmallBlank<dim>          blank(m, {1, 4, 2});
    const parameters::Run         &prm   = blank.prm;
    auto                          &state = blank.state;
    const material::DamageCriteria damage(prm.material);

    // u = (diag(e^l) - I) X at every node.
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(state.reference_mapping,
                                         state.dof_handler,
                                         points);
    std::vector<types::global_dof_index> dofs(state.fe.n_dofs_per_cell());
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (state.owned.is_element(dofs[i]))
              {
                const unsigned int c =
                  state.fe.system_to_component_index(i).first;
                state.displacement[dofs[i]] =
                  (std::exp(log_stretch[c]) - 1) * points[dofs[i]][c];
              }
        }
    state.displacement.compress(VectorOperation::insert);
    state.displacement_ghost = state.displacement;
    state.update_mapping();
    state.update_contact_areas();

    postprocess::SheetMeasures<dim> sheet(prm);
    sheet.measure(state, damage);
    const double t       = std::exp(log_stretch[dim - 1]);
    double       worst_t = 0, worst_major = 0, worst_minor = 0;
    for (const auto &c : sheet.columns())
      {
        worst_t     = std::max(worst_t, std::abs(c.thickness / t - 1));
        worst_major = std::max(worst_major, std::abs(c.major - major));
        worst_minor = std::max(worst_minor, std::abs(c.minor - minor));
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        test::close(name + ": columns measured",
                    sheet.columns().size() > 5,
                    1,
                    0);
        test::close(name + ": thickness / t0 exp(eps_3) - 1",
                    worst_t,
                    0,
                    1e-12);
        test::close(name + ": major strain", worst_major, 0, 1e-12);
        test::close(name + ": minor strain", worst_minor, 0, 1e-12);
      }
    test::close(name + ": summary minimum thickness",
                sheet.summary().min_thickness,
                t,
                1e-12);
    test::close(name + ": summary thinning (%)",
                sheet.summary().max_thinning,
                100 * (1 - t),
                1e-9);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     e = 0.2;
  Tensor<1, 3>                     plane, biaxial3;
  plane[0]    = e;
  plane[2]    = -e;
  biaxial3[0] = biaxial3[1] = e;
  biaxial3[2]               = -2 * e;
  Tensor<1, 2> biaxial2;
  biaxial2[0] = e;
  biaxial2[1] = -2 * e;
  check<3>("quarter, plane strain", model::Model::quarter, plane, e, 0);
  check<3>("quarter, equibiaxial", model::Model::quarter, biaxial3, e, e);
  check<2>("axisymmetric, equibiaxial",
           model::Model::axisymmetric,
           biaxial2,
           e,
           e);
  return test::result();
}
