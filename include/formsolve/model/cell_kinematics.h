// Kinematics on one cell: FEValues at a quadrature rule, in the current
// (and optionally the reference) configuration. Every integral over the sheet
// goes through this class, so the volume element and the 3x3 rates are the
// same everywhere (assembly, history, volume and strain integrals, output).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/model/kinematics.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace model
  {
    template <int dim>
    class CellKinematics
    {
    public:
      using CellIterator =
        typename dealii::DoFHandler<dim>::active_cell_iterator;
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// @p extra: further FEValues flags (e.g. update_jacobians for
      /// mapped_axis()). With @p reference, dV_reference() is available.
      CellKinematics(const Kinematics<dim>            &kinematics,
                     const dealii::Mapping<dim>       &mapping,
                     const dealii::FiniteElement<dim> &fe,
                     const dealii::Quadrature<dim>    &quadrature,
                     const dealii::UpdateFlags   extra = dealii::update_default,
                     const dealii::Mapping<dim> *reference = nullptr);

      void reinit(const CellIterator &cell);

      unsigned int n_points() const { return n_q; }
      unsigned int n_shape_functions() const { return component.size(); }

      /// Volume element at point q, current configuration (mm^3).
      double dV(const unsigned int q) const { return current_dV[q]; }
      /// The same in the reference (initial) configuration.
      double dV_reference(const unsigned int q) const;

      /// 3x3 rates of deformation of the ghosted vector @p v at all points.
      void rates(const VectorType                   &v,
                 std::vector<SymmetricTensor<2, 3>> &D) const;

      /// Strains B_i of all shape functions at point q.
      void shape_strains(const unsigned int        q,
                         std::vector<ShapeStrain> &B) const;

      /// The unit direction of reference axis @p axis at point q, mapped to
      /// the current configuration, in the 3x3 frame (needs update_jacobians).
      Tensor<1, 3> mapped_axis(const unsigned int q,
                               const unsigned int axis) const;

      /// dx/dX at point q from the reference (initial) configuration, in
      /// the model's dim x dim frame (needs update_jacobians and the
      /// reference mapping).
      Tensor<2, dim> deformation_gradient(const unsigned int q) const;

      const dealii::FEValues<dim> &fe_values() const { return fv; }

    private:
      const Kinematics<dim>                 &kinematics;
      dealii::FEValues<dim>                  fv;
      std::unique_ptr<dealii::FEValues<dim>> reference_fv;
      unsigned int                           n_q;
      std::vector<unsigned int>              component;
      std::vector<double>                    current_dV;
      mutable std::vector<Tensor<2, dim>>    gradients;
      mutable std::vector<Tensor<1, dim>>    values;
    };
  } // namespace model
} // namespace formsolve
