#include <formsolve/model/dimensions.h>
#include <formsolve/state/cell_points.h>

namespace formsolve
{
  namespace state
  {
    using namespace dealii;

    template <int dim>
    CellPoints<dim>::CellPoints(const material::RigidViscoplastic &material,
                                const model::Kinematics<dim>      &kinematics,
                                const Mapping<dim>                &mapping,
                                const Mapping<dim>       &reference_mapping,
                                const FiniteElement<dim> &fe,
                                const Quadrature<dim>    &full,
                                const Quadrature<dim>    &reduced,
                                const UpdateFlags         extra,
                                const material::PointFrames<dim> *frames)
        : frame(material)
        , cached(frames)
        , kf(kinematics,
             mapping,
             fe,
             full,
             frames ? extra : extra | frame.update_flags(),
             frame.needs_reference() && !frames ? &reference_mapping : nullptr)
        , kr(kinematics,
             mapping,
             fe,
             reduced,
             update_default,
             &reference_mapping)
    {}

    template <int dim>
    void CellPoints<dim>::reinit(const CellIterator                  &cell,
                                 const TrilinosWrappers::MPI::Vector &v)
    {
      kf.reinit(cell);
      kr.reinit(cell);
      if (cached)
        {
          Assert(cached->points_per_cell() == kf.n_points(),
                 ExcDimensionMismatch(cached->points_per_cell(),
                                      kf.n_points()));
          frame.reinit(cached->cell(cell->active_cell_index()), kf.n_points());
        }
      else
        frame.reinit(kf);
      kf.rates(v, D);
    }

#define INSTANTIATE(dim) template class CellPoints<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
