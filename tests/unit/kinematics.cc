// The kinematics layer on one cell, for a velocity field that Q1 represents
// exactly: the 3x3 rate of deformation (with the hoop rate v_r/r in
// axisymmetry), its linearisation (sum_i v_i B_i = D, so residual and tangent
// see the same strain), and the volume element (2 pi r JxW: the ring volume).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <formsolve/model/kinematics.h>

#include "check.h"

using namespace dealii;
using namespace formsolve::model;

namespace
{
  // v = A x + b (linear in the coordinates).
  template <int dim>
  Tensor<1, dim> velocity(const Point<dim> &x)
  {
    Tensor<1, dim> v;
    for (unsigned int i = 0; i < dim; ++i)
      {
        v[i] = 0.1 * (i + 1);
        for (unsigned int j = 0; j < dim; ++j)
          v[i] += (0.3 * i - 0.7 * j + 0.2 * i * j + 0.4) * x[j];
      }
    return v;
  }

  template <int dim>
  void
  check(const bool axisymmetric, const Point<dim> &lo, const Point<dim> &hi)
  {
    const std::string name =
      axisymmetric ? "axisymmetric" : std::to_string(dim) + "-D";
    Triangulation<dim> tria;
    GridGenerator::hyper_rectangle(tria, lo, hi);
    FESystem<dim>   fe(FE_Q<dim>(1), dim);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    MappingQ<dim>         mapping(1);
    const Kinematics<dim> kin(axisymmetric);
    const QGauss<dim>     quadrature(2);
    FEValues<dim>         fv(mapping,
                     fe,
                     quadrature,
                     update_values | update_gradients | update_JxW_values |
                       update_quadrature_points);
    fv.reinit(dofs.begin_active());

    // Nodal values of the linear field.
    std::vector<Point<dim>> support(fe.n_dofs_per_cell());
    Vector<double>          v(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < v.size(); ++i)
      {
        const auto c = fe.system_to_component_index(i);
        v[i] = velocity<dim>(dofs.begin_active()->vertex(c.second))[c.first];
      }

    // Its exact gradient.
    Tensor<2, dim> grad;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          Point<dim> e;
          e[j]       = 1;
          grad[i][j] = velocity<dim>(e)[i] - velocity<dim>(Point<dim>())[i];
        }

    SymmetricTensor<2, 3> S; // an arbitrary symmetric test tensor
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        S[i][j] = 1.0 + i - 0.5 * j + 0.25 * i * j;

    double volume = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const Point<dim> &x = fv.quadrature_point(q);
        const auto D = kin.rate_of_deformation(grad, velocity<dim>(x), x);
        if (axisymmetric)
          test::close(name + ": hoop rate v_r/r",
                      D[2][2],
                      velocity<dim>(x)[0] / x[0],
                      1e-12);
        else if (dim == 2)
          test::close(name + ": no out-of-plane rate", D[2][2], 0, 0);
        // sum_i v_i B_i must be D: compare S : D and tr D.
        double SD = 0, trD = 0;
        for (unsigned int i = 0; i < v.size(); ++i)
          {
            const auto B =
              kin.shape_strain(fe.system_to_component_index(i).first,
                               fv.shape_grad(i, q),
                               fv.shape_value(i, q),
                               x);
            SD += v[i] * B.contract(S);
            trD += v[i] * B.trace();
          }
        test::close(name + ": sum v_i S:B_i = S:D",
                    SD,
                    scalar_product(S, D),
                    1e-12);
        test::close(name + ": sum v_i tr B_i = tr D", trD, trace(D), 1e-12);
        // B_i : B_j is the bilinear form of the strains: check on i = j.
        const auto B0 =
          kin.shape_strain(0, fv.shape_grad(0, q), fv.shape_value(0, q), x);
        SymmetricTensor<2, 3> B0t;
        for (unsigned int k = 0; k < 3; ++k)
          {
            B0t[0][k] += (k == 0 ? 1. : 0.5) * B0.gradient[k];
          }
        B0t[2][2] += B0.hoop;
        test::close(name + ": B_0 : B_0", contract(B0, B0), B0t * B0t, 1e-12);
        volume += fv.JxW(q) * kin.volume_factor(x);
      }
    double exact = 1;
    for (unsigned int d = 0; d < dim; ++d)
      exact *= hi[d] - lo[d];
    if (axisymmetric)
      exact = M_PI * (hi[0] * hi[0] - lo[0] * lo[0]) * (hi[1] - lo[1]);
    test::close(name + ": volume", volume, exact, 1e-12 * exact);
  }
} // namespace

int main()
{
  check<2>(true, Point<2>(0.5, -1), Point<2>(2, 0.5));
  check<2>(false, Point<2>(0.5, -1), Point<2>(2, 0.5));
  check<3>(false, Point<3>(0.5, -1, 0), Point<3>(2, 0.5, 0.3));
  return test::result();
}
