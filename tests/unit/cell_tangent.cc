// The matrix-product form of the cell tangent (solver/cell_tangent) against
// the contraction it replaces, B_i : C : B_j per DoF pair and point, with
// ShapeStrain's own contraction, on a distorted cell: 2-D axisymmetric
// (hoop terms), plane 2-D and 3-D, Q1 and Q2, with arbitrary per-point
// viscosities and rate vectors. Equal to round-off, symmetric. The general
// form (a 6x6 tangent with no structure) against B_i : C : B_j summed
// directly.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <formsolve/forming/cell_tangent.h>
#include <formsolve/model/cell_kinematics.h>

#include "check.h"

#include <cmath>

using namespace dealii;
using namespace formsolve;

namespace
{
  /// A fourth-order tensor with both symmetries and no structure.
  SymmetricTensor<4, 3> general_tensor(const unsigned int q)
  {
    SymmetricTensor<4, 3> C;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = k; l < 3; ++l)
            {
              const unsigned int a = 3 * i + j, b = 3 * k + l;
              C[i][j][k][l] = std::cos(0.3 * (a * b) + 0.7 * (a + b) + q) +
                              (a == b ? 3. : 0.);
            }
    return C;
  }

  /// The general form (CellTangent::add_general) against B_i : C : B_j
  /// summed directly, for a tangent with no structure, on the same cell.
  template <int dim>
  void check_general(const std::string                &name,
                     solver::CellTangent<dim>         &tangent,
                     const model::CellKinematics<dim> &kf,
                     const model::CellKinematics<dim> &kr,
                     const unsigned int                n)
  {
    FullMatrix<double>              expected(n, n), K(n, n);
    std::vector<model::ShapeStrain> B;
    std::vector<double>             tr(n);
    for (unsigned int q = 0; q < kf.n_points(); ++q)
      {
        kf.shape_strains(q, B);
        const SymmetricTensor<4, 3> C = general_tensor(q);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            expected(i, j) += B[i].tensor() * C * B[j].tensor();
        tangent.add_general(q, B, C);
      }
    for (unsigned int q = 0; q < kr.n_points(); ++q)
      {
        kr.shape_strains(q, B);
        for (unsigned int i = 0; i < n; ++i)
          tr[i] = B[i].trace();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            expected(i, j) += 20. * tr[i] * tr[j];
        tangent.add_volumetric(q, tr, 20.);
      }
    tangent.finish(K);
    double scale = 0, error = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          scale = std::max(scale, std::abs(expected(i, j)));
          error = std::max(error, std::abs(K(i, j) - expected(i, j)));
        }
    test::close(name + ": general C, |K - B:C:B| / max|K|",
                error / scale,
                0,
                1e-13);
  }

  template <int dim>
  void check(const bool axisymmetric, const unsigned int degree)
  {
    const std::string name =
      (axisymmetric ? "axisymmetric" : std::to_string(dim) + "-D") + " Q" +
      std::to_string(degree);
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 1., 2.); // r in [1, 2]
    // A skewed, non-parallel cell: every gradient component is non-zero.
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> x = p;
        x[0] += 0.2 * p[dim - 1] * p[dim - 1];
        x[dim - 1] += 0.15 * p[0] + 0.05 * p[0] * p[0];
        if (dim == 3)
          x[1] += 0.1 * p[2] - 0.07 * p[0];
        return x;
      },
      tria);
    FESystem<dim>   fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim> dofs(tria);
    dofs.distribute_dofs(fe);
    MappingQ<dim>                mapping(1);
    const model::Kinematics<dim> kin(axisymmetric);
    const QGauss<dim>            full(degree + 1), reduced(degree);
    model::CellKinematics<dim>   kf(kin, mapping, fe, full);
    model::CellKinematics<dim>   kr(kin, mapping, fe, reduced);
    solver::CellTangent<dim>     tangent(fe,
                                     full.size(),
                                     reduced.size(),
                                     axisymmetric);
    kf.reinit(dofs.begin_active());
    kr.reinit(dofs.begin_active());

    const unsigned int              n = fe.n_dofs_per_cell();
    FullMatrix<double>              expected(n, n), K(n, n);
    std::vector<model::ShapeStrain> B;
    std::vector<double>             s(n), u(n), tr(n);
    for (unsigned int q = 0; q < full.size(); ++q)
      {
        kf.shape_strains(q, B);
        const double mu = 1.3 + 0.4 * std::sin(3. * q);
        for (unsigned int i = 0; i < n; ++i)
          {
            s[i] = std::cos(0.7 * i + q);
            u[i] = std::sin(1.1 * i - 0.3 * q);
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            expected(i, j) += 2. * mu *
                                (model::contract(B[i], B[j]) -
                                 B[i].trace() * B[j].trace() / 3.) +
                              s[i] * u[j] + u[i] * s[j];
        tangent.add_deviatoric(q, B, mu, s, u);
      }
    for (unsigned int q = 0; q < reduced.size(); ++q)
      {
        kr.shape_strains(q, B);
        const double w = 50. + q;
        for (unsigned int i = 0; i < n; ++i)
          tr[i] = B[i].trace();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            expected(i, j) += w * tr[i] * tr[j];
        tangent.add_volumetric(q, tr, w);
      }
    tangent.finish(K);

    double scale = 0, error = 0, asymmetry = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          scale     = std::max(scale, std::abs(expected(i, j)));
          error     = std::max(error, std::abs(K(i, j) - expected(i, j)));
          asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
        }
    test::close(name + ": |K - contraction| / max|K|", error / scale, 0, 1e-13);
    test::close(name + ": |K - K^T| / max|K|", asymmetry / scale, 0, 1e-14);

    // finish() starts afresh: the next cell's matrix has nothing of this
    // one (here: the volumetric term alone, weight 1).
    FullMatrix<double> again(n, n), volumetric(n, n);
    for (unsigned int q = 0; q < reduced.size(); ++q)
      {
        kr.shape_strains(q, B);
        for (unsigned int i = 0; i < n; ++i)
          tr[i] = B[i].trace();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            volumetric(i, j) += tr[i] * tr[j];
        tangent.add_volumetric(q, tr, 1.);
      }
    tangent.finish(again);
    double carried = 0, vol_scale = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          carried = std::max(carried, std::abs(again(i, j) - volumetric(i, j)));
          vol_scale = std::max(vol_scale, std::abs(volumetric(i, j)));
        }
    test::close(name + ": second cell, |K - tr tr| / max|K|",
                carried / vol_scale,
                0,
                1e-13);
    check_general(name, tangent, kf, kr, n);
  }
} // namespace

int main()
{
  for (const unsigned int degree : {1u, 2u})
    {
      check<2>(true, degree);
      check<2>(false, degree);
      check<3>(false, degree);
    }
  return test::result();
}
