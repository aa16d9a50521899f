#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace model
  {
    using namespace dealii;

    template <int dim>
    CellKinematics<dim>::CellKinematics(const Kinematics<dim>    &kinematics,
                                        const Mapping<dim>       &mapping,
                                        const FiniteElement<dim> &fe,
                                        const Quadrature<dim>    &quadrature,
                                        const UpdateFlags         extra,
                                        const Mapping<dim>       *reference)
        : kinematics(kinematics)
        , fv(mapping,
             fe,
             quadrature,
             update_gradients | update_JxW_values | extra |
               kinematics.update_flags())
        , n_q(quadrature.size())
        , current_dV(quadrature.size())
        , gradients(quadrature.size())
        , values(quadrature.size())
    {
      if (reference != nullptr)
        reference_fv = std::make_unique<FEValues<dim>>(
          *reference,
          fe,
          quadrature,
          update_JxW_values | (extra & update_jacobians) |
            (kinematics.update_flags() & update_quadrature_points));
      component.resize(fe.n_dofs_per_cell());
      for (unsigned int i = 0; i < component.size(); ++i)
        component[i] = fe.system_to_component_index(i).first;
    }

    template <int dim>
    void CellKinematics<dim>::reinit(const CellIterator &cell)
    {
      fv.reinit(cell);
      for (unsigned int q = 0; q < n_q; ++q)
        current_dV[q] =
          fv.JxW(q) * (kinematics.axisymmetric()
                         ? kinematics.volume_factor(fv.quadrature_point(q))
                         : kinematics.depth());
      if (reference_fv)
        reference_fv->reinit(cell);
    }

    template <int dim>
    double CellKinematics<dim>::dV_reference(const unsigned int q) const
    {
      Assert(reference_fv, ExcInternalError());
      return reference_fv->JxW(q) *
             (kinematics.axisymmetric()
                ? kinematics.volume_factor(reference_fv->quadrature_point(q))
                : kinematics.depth());
    }

    template <int dim>
    void CellKinematics<dim>::rates(const VectorType                   &v,
                                    std::vector<SymmetricTensor<2, 3>> &D) const
    {
      const FEValuesExtractors::Vector velocity(0);
      fv[velocity].get_function_gradients(v, gradients);
      if (kinematics.axisymmetric())
        fv[velocity].get_function_values(v, values);
      D.resize(n_q);
      for (unsigned int q = 0; q < n_q; ++q)
        D[q] = kinematics.rate_of_deformation(gradients[q],
                                              values[q],
                                              kinematics.axisymmetric()
                                                ? fv.quadrature_point(q)
                                                : Point<dim>());
    }

    template <int dim>
    void CellKinematics<dim>::shape_strains(const unsigned int        q,
                                            std::vector<ShapeStrain> &B) const
    {
      const bool axi = kinematics.axisymmetric();
      B.resize(component.size());
      for (unsigned int i = 0; i < component.size(); ++i)
        B[i] =
          kinematics.shape_strain(component[i],
                                  fv.shape_grad(i, q),
                                  axi ? fv.shape_value(i, q) : 0.,
                                  axi ? fv.quadrature_point(q) : Point<dim>());
    }

    template <int dim>
    Tensor<1, 3> CellKinematics<dim>::mapped_axis(const unsigned int q,
                                                  const unsigned int axis) const
    {
      Tensor<1, dim> t;
      for (unsigned int d = 0; d < dim; ++d)
        t[d] = fv.jacobian(q)[d][axis];
      return Kinematics<dim>::embed(t / t.norm());
    }

    template <int dim>
    Tensor<2, dim>
    CellKinematics<dim>::deformation_gradient(const unsigned int q) const
    {
      Assert(reference_fv, ExcInternalError());
      return Tensor<2, dim>(fv.jacobian(q)) *
             invert(Tensor<2, dim>(reference_fv->jacobian(q)));
    }

#define INSTANTIATE(dim) template class CellKinematics<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace model
} // namespace formsolve
