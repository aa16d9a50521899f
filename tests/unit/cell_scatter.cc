// Assembly by position (solver/cell_scatter): a matrix assembled with the
// scatter for the cells it maps and distribute_local_to_global for the rest
// equals, entry by entry and to the bit, the matrix assembled with
// distribute_local_to_global alone. The mesh has hanging nodes and a
// boundary constraint, so both paths run; on 2 ranks cells with DoFs of the
// other rank also take the general path. In 2 and 3 dimensions.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/forming/cell_scatter.h>

#include "check.h"

#include <cmath>

using namespace dealii;

namespace
{
  template <int dim>
  void run()
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::subdivided_hyper_cube(tria, 4);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.3 &&
          cell->center()[1] < 0.6)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();

    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             1,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints,
                                             fe.component_mask(
                                               FEValuesExtractors::Scalar(0)));
    constraints.close();

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    TrilinosWrappers::SparseMatrix general, scattered;
    general.reinit(owned, owned, dsp, comm);
    scattered.reinit(general);
    TrilinosWrappers::MPI::Vector r1(owned, comm), r2(owned, comm);

    formsolve::solver::CellScatter<dim> scatter;
    scatter.reinit(dof_handler, constraints, scattered);

    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   K(n, n);
    Vector<double>                       r(n);
    std::vector<types::global_dof_index> dofs(n);
    unsigned int owned_cells = 0, mapped = 0, expected = 0;
    // Twice over: the second pass adds to the first (sums, not writes).
    for (unsigned int pass = 0; pass < 2; ++pass)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Point<dim> c = cell->center();
            for (unsigned int i = 0; i < n; ++i)
              {
                r[i] = std::sin(3. * i + 7. * c[0] + pass);
                for (unsigned int j = 0; j < n; ++j)
                  K(i, j) = std::sin(1.3 * i + 0.7 * j * j + 11. * c[0] +
                                     5. * c[1] + c[dim - 1] + pass);
              }
            cell->get_dof_indices(dofs);
            // Which cells the scatter must map, derived here: every DoF
            // owned by this rank and unconstrained.
            bool plain = true;
            for (const auto dof : dofs)
              plain = plain && owned.is_element(dof) &&
                      !constraints.is_constrained(dof);
            expected += pass == 0 && plain;
            constraints.distribute_local_to_global(K, r, dofs, general, r1);
            if (scatter.maps(cell->active_cell_index()))
              {
                scatter.add(cell->active_cell_index(), K, scattered);
                constraints.distribute_local_to_global(r, dofs, r2);
                mapped += pass == 0;
              }
            else
              constraints.distribute_local_to_global(K, r, dofs, scattered, r2);
            owned_cells += pass == 0;
          }
    general.compress(VectorOperation::add);
    scattered.compress(VectorOperation::add);
    r1.compress(VectorOperation::add);
    r2.compress(VectorOperation::add);

    const std::string d    = std::to_string(dim) + "d: ";
    const double      norm = general.frobenius_norm();
    test::close(d + "matrix norm positive", norm > 1, 1, 0);
    scattered.add(-1., general);
    test::close(d + "|scattered - general|_F",
                scattered.frobenius_norm(),
                0,
                0);
    r2 -= r1;
    test::close(d + "|residual difference|", r2.l2_norm(), 0, 0);
    const unsigned int all_owned  = Utilities::MPI::sum(owned_cells, comm);
    const unsigned int all_mapped = Utilities::MPI::sum(mapped, comm);
    test::close(d + "mapped cells: owned, unconstrained DoFs only",
                mapped,
                expected,
                0);
    // Both paths ran: some cells mapped, some (constrained) not.
    test::close(d + "some cells mapped", all_mapped > 0, 1, 0);
    test::close(d + "some cells not mapped", all_mapped < all_owned, 1, 0);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>();
  run<3>();
  return test::result();
}
