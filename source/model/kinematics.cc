#include <deal.II/base/exceptions.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/model/kinematics.h>

#include <cmath>

namespace formsolve
{
  namespace model
  {
    using namespace dealii;

    template <int dim>
    Kinematics<dim>::Kinematics(const bool axisymmetric, const double depth)
        : axi(axisymmetric)
        , width(depth)
    {
      Assert(dim == 2 || !axisymmetric, ExcInternalError());
      Assert(depth > 0 && (dim == 2 || depth == 1), ExcInternalError());
    }

    template <int dim>
    UpdateFlags Kinematics<dim>::update_flags() const
    {
      // The radius of the point enters the hoop rate and the volume element.
      return axi ? (update_quadrature_points | update_values) : update_default;
    }

    template <int dim>
    double Kinematics<dim>::volume_factor(const Point<dim> &x) const
    {
      return axi ? 2. * M_PI * x[0] : width;
    }

    template <int dim>
    SymmetricTensor<2, 3>
    Kinematics<dim>::rate_of_deformation(const Tensor<2, dim> &grad_v,
                                         const Tensor<1, dim> &v,
                                         const Point<dim>     &x) const
    {
      SymmetricTensor<2, 3> D;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          D[i][j] = 0.5 * (grad_v[i][j] + grad_v[j][i]);
      if (axi)
        {
          // Quadrature points lie inside cells, so r > 0 here.
          Assert(x[0] > 0, ExcInternalError());
          D[2][2] = v[0] / x[0];
        }
      return D;
    }

    template <int dim>
    ShapeStrain Kinematics<dim>::shape_strain(const unsigned int    c,
                                              const Tensor<1, dim> &grad,
                                              const double          phi,
                                              const Point<dim>     &x) const
    {
      ShapeStrain B;
      B.component = c;
      B.gradient  = embed(grad);
      if (axi && c == 0)
        B.hoop = phi / x[0];
      return B;
    }

    template <int dim>
    Tensor<1, 3> Kinematics<dim>::embed(const Tensor<1, dim> &a)
    {
      Tensor<1, 3> b;
      for (unsigned int d = 0; d < dim; ++d)
        b[d] = a[d];
      return b;
    }

#define INSTANTIATE(dim) template class Kinematics<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace model
} // namespace formsolve
