// Tangent and residual of the body (flow formulation, no contact), through
// the model's kinematics and the material law.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/forming/dual_stress.h>
#include <formsolve/material/point_frames.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/model/kinematics.h>
#include <formsolve/state/quadrature_history.h>

namespace formsolve
{
  namespace solver
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;
    using state::HistoryStorage;

    template <int dim>
    class CellScatter;

    template <int dim>
    class Assembler
    {
    public:
      /// @p reference_mapping maps the initial configuration: the volumetric
      /// term drives each cell back to its initial volume (doc/theory.md).
      Assembler(const material::RigidViscoplastic &material,
                const model::Kinematics<dim>      &kinematics,
                const dealii::Mapping<dim>        &reference_mapping,
                const unsigned int                 degree);

      /// Body residual r = f_int (and the tangent if @p matrix is not null)
      /// at velocity @p v (ghosted), geometry given by @p mapping; matrix and
      /// residual are zeroed first and compressed at the end. With @p dual,
      /// the Newton tangent is the stress-velocity one (dual_stress.h), and
      /// the dual directions of this iterate are kept as its trial values.
      /// With @p frames, the point frames of this configuration at
      /// quadrature() are read from it. Returns the norm of the element
      /// internal-force vectors, a scale for |r|.
      double
      assemble_body(const dealii::DoFHandler<dim>           &dof_handler,
                    const dealii::Mapping<dim>              &mapping,
                    const dealii::AffineConstraints<double> &constraints,
                    const VectorType                        &v,
                    const HistoryStorage<dim>               &history,
                    const double                             dt,
                    const bool                               newton,
                    MatrixType                              *matrix,
                    VectorType                              &residual,
                    DualStress                              *dual    = nullptr,
                    const CellScatter<dim>                  *scatter = nullptr,
                    const material::PointFrames<dim> *frames = nullptr) const;

      /// Assemble the deviatoric tangent through the material's general
      /// 6x6 tangent even where it has the isotropic form (tests: both give
      /// the same matrix).
      void use_general_tangent() { product_form = false; }

      /// The strain rate below which the flow law is linear (1/s).
      double cutoff_rate() const { return material.cutoff_rate(); }
      bool   smooth_rigid_zone() const { return material.smooth_rigid_zone(); }

      const dealii::Quadrature<dim>     &quadrature() const { return full; }
      const material::RigidViscoplastic &law() const { return material; }

    private:
      const material::RigidViscoplastic &material;
      const model::Kinematics<dim>      &kinematics;
      const dealii::Mapping<dim>        &reference_mapping;
      dealii::QGauss<dim>                full;    // deviatoric part
      dealii::QGauss<dim>                reduced; // volumetric part
      bool product_form; // CellTangent::add_deviatoric, else add_general
    };
  } // namespace solver
} // namespace formsolve
