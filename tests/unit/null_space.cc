// The near null space handed to ML (solver/null_space.cc): every mode, as a
// finite-element velocity field, must be a rigid motion (zero symmetric
// gradient at every quadrature point), the translations must be unit fields,
// the modes must be independent, and the node coordinates must be the
// support points of the nodes' first components. 2-D and 3-D, on a distorted
// mesh, on 1 rank and on 2 (each rank its own DoFs).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/solver/null_space.h>

#include "check.h"

#include <map>

using namespace dealii;

namespace
{
  template <int dim>
  void check(const unsigned int degree)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              std::vector<unsigned int>(dim, 3),
                                              Point<dim>(),
                                              dim == 3
                                                ? Point<dim>(20., 10., 0.8)
                                                : Point<dim>(20., 0.8));
    // A sheared, bent mesh: the modes must follow the real node positions.
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> q = p;
        q[dim - 1] += 0.05 * p[0] * p[0];
        q[0] += 0.3 * p[dim - 1];
        return q;
      },
      tria);
    tria.refine_global(1);
    FESystem<dim>   fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    const IndexSet owned = dofs.locally_owned_dofs();
    MappingQ<dim>  mapping(1);
    const auto     space =
      formsolve::solver::rigid_body_modes(mapping, dofs, owned);
    const unsigned int n = owned.n_elements();
    const std::string  tag =
      std::to_string(dim) + "-D, Q" + std::to_string(degree) + ", rank " +
      std::to_string(Utilities::MPI::this_mpi_process(comm));
    test::close(tag + ": modes", space.n_modes, dim == 3 ? 6 : 3, 0);
    test::close(tag + ": length", space.modes.size(), space.n_modes * n, 0);

    // Node coordinates: the support point of each node's first component.
    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dofs, points);
    double coordinate_error = 0;
    for (unsigned int node = 0; node < n / dim; ++node)
      {
        const Point<dim> &p = points[owned.nth_index_in_set(node * dim)];
        coordinate_error =
          std::max({coordinate_error,
                    std::abs(space.x[node] - p[0]),
                    std::abs(space.y[node] - p[1]),
                    std::abs(space.z[node] - (dim == 3 ? p[2] : 0.))});
      }
    test::close(tag + ": node coordinates", coordinate_error, 0, 0);

    // Each mode as a velocity field on the locally owned cells (their DoFs
    // may belong to the neighbour: gather all ranks' entries).
    Vector<double>                   field(dofs.n_dofs());
    QGauss<dim>                      quadrature(degree + 1);
    FEValues<dim>                    values(mapping,
                         fe,
                         quadrature,
                         update_gradients | update_values);
    FullMatrix<double>               gram(space.n_modes, space.n_modes);
    std::vector<std::vector<double>> all_modes(space.n_modes);
    for (unsigned int m = 0; m < space.n_modes; ++m)
      {
        field = 0;
        for (unsigned int i = 0; i < n; ++i)
          field[owned.nth_index_in_set(i)] = space.modes[m * n + i];
        Utilities::MPI::sum(field, comm, field);
        all_modes[m].assign(field.begin(), field.end());
        double strain = 0, translation_error = 0;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              values.reinit(cell);
              std::vector<Tensor<2, dim>>              grad(quadrature.size());
              std::vector<Vector<double>>              u(quadrature.size(),
                                            Vector<double>(dim));
              std::vector<std::vector<Tensor<1, dim>>> g(
                quadrature.size(),
                std::vector<Tensor<1, dim>>(dim));
              values.get_function_gradients(field, g);
              values.get_function_values(field, u);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      strain =
                        std::max(strain, std::abs(g[q][a][b] + g[q][b][a]));
                  if (m < dim)
                    for (unsigned int a = 0; a < dim; ++a)
                      translation_error =
                        std::max(translation_error,
                                 std::abs(u[q][a] - (a == m ? 1. : 0.)));
                }
            }
        test::close(tag + ": mode " + std::to_string(m) + " rigid",
                    Utilities::MPI::max(strain, comm),
                    0,
                    1e-10); // a wrong sign gives 2
        if (m < dim)
          test::close(tag + ": mode " + std::to_string(m) + " unit translation",
                      Utilities::MPI::max(translation_error, comm),
                      0,
                      1e-14);
      }
    for (unsigned int a = 0; a < space.n_modes; ++a)
      for (unsigned int b = 0; b < space.n_modes; ++b)
        for (unsigned int k = 0; k < dofs.n_dofs(); ++k)
          gram(a, b) += all_modes[a][k] * all_modes[b][k];
    // Independent modes: the Gram matrix is far from singular.
    gram.gauss_jordan();
    test::close(tag + ": Gram matrix invertible, finite inverse",
                std::isfinite(gram.frobenius_norm()) &&
                  gram.frobenius_norm() < 1e6,
                1,
                0);
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>(1);
  check<3>(1);
  check<3>(2);
  return test::result();
}
