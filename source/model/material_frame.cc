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
      // The sheet plane is (x, y): axes 0, 1 in 3-D; in a 2-D section,
      // axis 0 and the third axis of the 3x3 frame (y in plane strain, the
      // hoop direction in axisymmetry), and ND is axis 1 (z).
      const unsigned int y = dim == 3 ? 1 : 2, z = dim == 3 ? 2 : 1;
      const double       c = std::cos(rolling_direction),
                   s       = std::sin(rolling_direction);
      start[0][0]          = c; // RD
      start[y][0]          = s;
      start[0][1]          = -s; // TD
      start[y][1]          = c;
      start[z][2]          = 1; // ND
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
