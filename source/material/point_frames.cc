#include <formsolve/material/hill_orientation.h>
#include <formsolve/material/point_frames.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    template <int dim>
    void PointFrames<dim>::compute(const RigidViscoplastic      &material,
                                   const model::Kinematics<dim> &kinematics,
                                   const DoFHandler<dim>        &dofs,
                                   const Mapping<dim>           &mapping,
                                   const Mapping<dim>    &reference_mapping,
                                   const Quadrature<dim> &quadrature)
    {
      valid    = true;
      n_points = quadrature.size();
      frames.clear();
      if (material.isotropic())
        return;
      HillOrientation<dim>       orientation(material);
      model::CellKinematics<dim> k(kinematics,
                                   mapping,
                                   dofs.get_fe(),
                                   quadrature,
                                   orientation.update_flags(),
                                   &reference_mapping);
      frames.resize(std::size_t(dofs.get_triangulation().n_active_cells()) *
                    n_points);
      for (const auto &c : dofs.active_cell_iterators())
        if (c->is_locally_owned())
          {
            k.reinit(c);
            orientation.reinit(k);
            for (unsigned int q = 0; q < n_points; ++q)
              frames[std::size_t(c->active_cell_index()) * n_points + q] =
                orientation.frame(q);
          }
    }

#define INSTANTIATE(dim) template class PointFrames<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace material
} // namespace formsolve
