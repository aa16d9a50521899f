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
                                const UpdateFlags         extra)
        : frame(material)
        , kf(kinematics,
             mapping,
             fe,
             full,
             extra | frame.update_flags(),
             frame.needs_reference() ? &reference_mapping : nullptr)
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
      frame.reinit(kf);
      kf.rates(v, D);
    }

#define INSTANTIATE(dim) template class CellPoints<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
