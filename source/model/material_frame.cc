#include <formsolve/model/dimensions.h>
#include <formsolve/model/material_frame.h>

#include <cmath>

namespace formsolve
{
  namespace model
  {
    using namespace dealii;

    template <int dim>
    Tensor<2, dim> polar_rotation(const Tensor<2, dim> &F)
    {
      // The orthogonal tensor nearest F (deal.II's, through its SVD) is the
      // rotation of F = R U for det F > 0.
      return project_onto_orthogonal_tensors(F);
    }

    template <int dim>
    MaterialFrame<dim>::MaterialFrame(const double rolling_direction)
    {
      if (dim == 3)
        {
          const double c = std::cos(rolling_direction),
                       s = std::sin(rolling_direction);
          start[0][0]    = c; // RD
          start[1][0]    = s;
          start[0][1]    = -s; // TD
          start[1][1]    = c;
          start[2][2]    = 1; // ND
        }
      else
        {
          start[0][0] = 1; // RD radial
          start[2][1] = 1; // TD hoop
          start[1][2] = 1; // ND axial
        }
    }

    template <int dim>
    Tensor<2, 3> MaterialFrame<dim>::operator()(const Tensor<2, dim> &F) const
    {
      const Tensor<2, dim> R = polar_rotation(F);
      Tensor<2, 3>         R3;
      R3[2][2] = 1; // the hoop direction of the axisymmetric model
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          R3[i][j] = R[i][j];
      return R3 * start;
    }

#define INSTANTIATE(dim)             \
  template class MaterialFrame<dim>; \
  template Tensor<2, dim> polar_rotation(const Tensor<2, dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace model
} // namespace formsolve
