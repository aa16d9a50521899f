#include <formsolve/material/hill_orientation.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace material
  {
    using dealii::Tensor;

    template <int dim>
    HillOrientation<dim>::HillOrientation(const RigidViscoplastic &material)
        : material(material)
        , initial(material.rolling_direction())
    {}

    template <int dim>
    void HillOrientation<dim>::reinit(const model::CellKinematics<dim> &k)
    {
      if (material.isotropic())
        return;
      frames.resize(k.n_points());
      maps.resize(k.n_points());
      for (unsigned int q = 0; q < k.n_points(); ++q)
        {
          frames[q] = initial(k.deformation_gradient(q));
          maps[q]   = material.hill_map(frames[q]);
        }
    }

    template <int dim>
    void HillOrientation<dim>::reinit(const Tensor<2, 3> *cell_frames,
                                      const unsigned int  n_points)
    {
      if (material.isotropic())
        return;
      frames.assign(cell_frames, cell_frames + n_points);
      maps.resize(n_points);
      for (unsigned int q = 0; q < n_points; ++q)
        maps[q] = material.hill_map(frames[q]);
    }

#define INSTANTIATE(dim) template class HillOrientation<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace material
} // namespace formsolve
