// The through-thickness average of the fracture integrals per column of
// elements (postprocess::ThroughThicknessDamage) on a mesh refined twice in
// the upper layers only, so that columns hold cells of three levels and
// hanging nodes: with I = z^2 + z/2 + 0.01 X0 at every point (z the reference
// height, X0 the reference x of the centre of the cell's coarse planform
// cell), every column's average is t0^2/3 + t0/4 + 0.01 X0 exactly; the
// largest and its column's heights summing to t0 are checked to 1e-12, every
// cell's value (a float VTU field) to 1e-6. Axisymmetric and quarter models, 1
// and 2 ranks. A column that misses a cell of another level or rank, a wrong
// weight or a cell counted twice fails here.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/postprocess/through_thickness.h>

#include "check.h"
#include "small_blank.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  template <int dim>
  double coarse_x(const typename Triangulation<dim>::cell_iterator &cell)
  {
    auto c = cell;
    while (c->level() > 0)
      c = c->parent();
    double x = 0;
    for (unsigned int v = 0; v < (1u << (dim - 1)); ++v)
      x += c->vertex(v)[0] / (1u << (dim - 1));
    return x;
  }

  template <int dim>
  void check(const std::string &name, const model::Model m)
  {
    test::SmallBlank<dim> blank(m, {1, 4, dim == 2 ? 3u : 2u});
    auto                 &state = blank.state;
    const double          t0    = blank.prm.geometry.thickness;

    // Refine the upper half near the axis, then its upper quarter again.
    for (const double z_above : {0.5 * t0, 0.75 * t0})
      {
        for (const auto &cell : state.tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[dim - 1] > z_above &&
              cell->center()[0] < 6)
            cell->set_refine_flag();
        state.tria.execute_coarsening_and_refinement();
      }
    state.setup_dofs();

    FEValues<dim> fv(state.reference_mapping,
                     state.fe,
                     state.history_rule,
                     update_quadrature_points);
    double        expected_max = 0;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          const double x0 = coarse_x<dim>(cell);
          expected_max    = std::max(expected_max, x0);
          auto h          = state.history.get_data(cell);
          for (unsigned int q = 0; q < h.size(); ++q)
            {
              const double z = fv.quadrature_point(q)[dim - 1];
              h[q]->oyane    = z * z + z / 2 + 0.01 * x0;
            }
        }
    const double column = t0 * t0 / 3 + t0 / 4;
    expected_max =
      column + 0.01 * Utilities::MPI::max(expected_max, MPI_COMM_WORLD);

    const material::DamageCriteria           damage(blank.prm.material);
    postprocess::ThroughThicknessDamage<dim> measure;
    const auto r = measure.measure(state, damage, true);
    std::cout << name << ": " << state.tria.n_global_levels() << " levels, "
              << state.tria.n_global_active_cells() << " cells\n";
    test::close(name + ": largest column average",
                r.oyane.value,
                expected_max,
                1e-12);
    test::close(name + ": column heights sum to t0", r.height_error, 0, 1e-12);
    double worst = 0;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        worst =
          std::max(worst,
                   std::abs(measure.cell_values()[cell->active_cell_index()] -
                            (column + 0.01 * coarse_x<dim>(cell))));
    test::close(name + ": every cell's column value",
                Utilities::MPI::max(worst, MPI_COMM_WORLD),
                0,
                1e-6);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("axisymmetric", model::Model::axisymmetric);
  check<3>("quarter", model::Model::quarter);
  return test::result();
}
