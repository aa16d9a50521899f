// The current-configuration mapping (model/current_mapping: MappingQCache
// with no cell similarity) against MappingQEulerian, the definition, on a
// mesh of equal rectangles (boxes) whose reference cells are translates of
// each other, under a displacement that makes them different: volume,
// first moment (the axisymmetric 2 pi r factor) and every JxW and point.
// deal.II 9.4's MappingQCache alone reuses the previous cell's Jacobians
// here and fails the volume check. Run on 1 and 2 ranks (ghost cells).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/model/current_mapping.h>

#include "check.h"

using namespace dealii;
using VectorType = TrilinosWrappers::MPI::Vector;

namespace
{
  template <int dim>
  class Displacement : public Function<dim>
  {
  public:
    Displacement()
        : Function<dim>(dim)
    {}
    double value(const Point<dim> &p, const unsigned int c) const override
    {
      return c == 0 ? 0.1 * p[0] * p[dim - 1] : 0.05 * p[0] * p[0] * (c + 1);
    }
  };

  template <int dim>
  void check(const unsigned int degree)
  {
    const std::string name =
      std::to_string(dim) + "-D Q" + std::to_string(degree);
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    std::vector<unsigned int>                 cells(dim, 2);
    cells[0] = 8;
    Point<dim> lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
      lo[d] = 1., hi[d] = 1. + (d == 0 ? 4. : 1.);
    GridGenerator::subdivided_hyper_rectangle(tria, cells, lo, hi);
    FESystem<dim>   fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    const IndexSet owned    = dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    MappingQ<dim>  reference(degree);
    VectorType     u(owned, MPI_COMM_WORLD),
      u_ghost(owned, relevant, MPI_COMM_WORLD);
    VectorTools::interpolate(reference, dofs, Displacement<dim>(), u);
    u_ghost = u;

    MappingQEulerian<dim, VectorType>     eulerian(degree, dofs, u_ghost);
    formsolve::model::CurrentMapping<dim> current(degree);
    current.initialize(reference, dofs, u, true);

    const QGauss<dim> quadrature(degree + 1);
    const auto        flags = update_JxW_values | update_quadrature_points;
    FEValues<dim>     fe_e(eulerian, fe, quadrature, flags);
    FEValues<dim>     fe_c(current, fe, quadrature, flags);
    double volume[2] = {0, 0}, moment[2] = {0, 0}, jxw = 0, point = 0;
    // Owned cells for the integrals; ghost cells too for the pointwise
    // checks (the cache is filled from the owned vector on every rank).
    for (const auto &cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
        {
          fe_e.reinit(cell);
          fe_c.reinit(cell);
          const double owned_cell = cell->is_locally_owned() ? 1. : 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              volume[0] += owned_cell * fe_e.JxW(q);
              volume[1] += owned_cell * fe_c.JxW(q);
              moment[0] +=
                owned_cell * fe_e.JxW(q) * fe_e.quadrature_point(q)[0];
              moment[1] +=
                owned_cell * fe_c.JxW(q) * fe_c.quadrature_point(q)[0];
              jxw   = std::max(jxw, std::abs(fe_e.JxW(q) - fe_c.JxW(q)));
              point = std::max(point,
                               fe_e.quadrature_point(q).distance(
                                 fe_c.quadrature_point(q)));
            }
        }
    for (double *x : {&volume[0], &volume[1], &moment[0], &moment[1]})
      *x = Utilities::MPI::sum(*x, MPI_COMM_WORLD);
    jxw   = Utilities::MPI::max(jxw, MPI_COMM_WORLD);
    point = Utilities::MPI::max(point, MPI_COMM_WORLD);
    test::close(name + ": volume", volume[1], volume[0], 1e-12 * volume[0]);
    test::close(name + ": first moment",
                moment[1],
                moment[0],
                1e-12 * moment[0]);
    test::close(name + ": largest JxW difference", jxw, 0, 1e-14);
    test::close(name + ": largest point difference", point, 0, 1e-14);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      check<2>(degree);
      check<3>(degree);
    }
  return test::result();
}
