// Tangent and residual of the body (flow formulation, no contact), and the
// integrals over the sheet, all through the model's kinematics.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/material/damage.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/model/kinematics.h>
#include <formsolve/simulation/quadrature_history.h>
#include <formsolve/solver/dual_stress.h>

namespace formsolve
{
  namespace solver
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;
    using simulation::HistoryStorage;

    /// A quantity stored at the quadrature points.
    using HistoryField = double simulation::QuadraturePointHistory::*;

    /// The largest value of a history field and where it is (current
    /// configuration), on all ranks.
    template <int dim>
    class CellScatter;

    template <int dim>
    struct HistoryMaximum
    {
      double             value = 0;
      dealii::Point<dim> location;
    };

    template <int dim>
    class Assembler
    {
    public:
      /// @p reference_mapping maps the initial configuration: the volumetric
      /// term drives each cell back to its initial volume (doc/theory.md).
      /// With @p damage, update_history() also integrates the damage
      /// criteria.
      Assembler(const material::RigidViscoplastic &material,
                const model::Kinematics<dim>      &kinematics,
                const dealii::Mapping<dim>        &reference_mapping,
                const unsigned int                 degree,
                const material::DamageCriteria    *damage = nullptr);

      /// Body residual r = f_int (and the tangent if @p matrix is not null)
      /// at velocity @p v (ghosted), geometry given by @p mapping; matrix and
      /// residual are zeroed first and compressed at the end. With @p dual,
      /// the Newton tangent is the stress-velocity one (dual_stress.h), and
      /// the dual directions of this iterate are kept as its trial values.
      /// Returns the norm of the element internal-force vectors, a scale for
      /// |r|.
      double assemble_body(const dealii::DoFHandler<dim>           &dof_handler,
                           const dealii::Mapping<dim>              &mapping,
                           const dealii::AffineConstraints<double> &constraints,
                           const VectorType                        &v,
                           const HistoryStorage<dim>               &history,
                           const double                             dt,
                           const bool                               newton,
                           MatrixType                              *matrix,
                           VectorType                              &residual,
                           DualStress             *dual    = nullptr,
                           const CellScatter<dim> *scatter = nullptr) const;

      /// Assemble the deviatoric tangent through the material's general
      /// 6x6 tangent even where it has the isotropic form (tests: both give
      /// the same matrix).
      void use_general_tangent() { product_form = false; }

      /// The strain rate below which the flow law is linear (1/s).
      double cutoff_rate() const { return material.cutoff_rate(); }
      bool   smooth_rigid_zone() const { return material.smooth_rigid_zone(); }

      /// After convergence: integrate strain, thickness strain and damage,
      /// store stresses.
      void update_history(const dealii::DoFHandler<dim> &dof_handler,
                          const dealii::Mapping<dim>    &mapping,
                          const VectorType              &v,
                          const double                   dt,
                          HistoryStorage<dim>           &history) const;

      /// Create history entries on the locally owned cells.
      /// Swaps each cell's volume offset c and its volume error
      /// e = ln(dV/dV0) - c (cell means at the reduced points): before an
      /// adaptation the history carries e to the new cells, after it each
      /// new cell takes c = ln(dV/dV0) - e, so that the volume correction
      /// goes on from the error of the cells it came from (doc/theory.md,
      /// eq. 5a). Cells left alone get their c back.
      void exchange_volume_offsets(const dealii::DoFHandler<dim> &dof_handler,
                                   const dealii::Mapping<dim>    &mapping,
                                   HistoryStorage<dim> &history) const;

      void initialize_history(const dealii::DoFHandler<dim> &dof_handler,
                              HistoryStorage<dim>           &history) const;

      /// Volume of the body in the configuration given by @p mapping (mm^3;
      /// the full ring in axisymmetry).
      double volume(const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping) const;

      /// Volume integral of a history field (e.g. the equivalent plastic
      /// strain: mm^3), current configuration: what refinement must carry
      /// over.
      double history_integral(const dealii::DoFHandler<dim> &dof_handler,
                              const dealii::Mapping<dim>    &mapping,
                              const HistoryStorage<dim>     &history,
                              const HistoryField             field) const;
      double strain_integral(const dealii::DoFHandler<dim> &dof_handler,
                             const dealii::Mapping<dim>    &mapping,
                             const HistoryStorage<dim>     &history) const
      {
        return history_integral(dof_handler,
                                mapping,
                                history,
                                &simulation::QuadraturePointHistory::strain);
      }

      /// Largest value of a history field at any quadrature point and its
      /// position.
      HistoryMaximum<dim>
      history_maximum(const dealii::DoFHandler<dim> &dof_handler,
                      const dealii::Mapping<dim>    &mapping,
                      const HistoryStorage<dim>     &history,
                      const HistoryField             field) const;

      /// Plastic power int sigma_bar rate dV plus the volumetric term (W = N
      /// mm/s).
      double internal_power(const dealii::DoFHandler<dim> &dof_handler,
                            const dealii::Mapping<dim>    &mapping,
                            const VectorType              &v,
                            const HistoryStorage<dim>     &history,
                            const double                   dt) const;

      const dealii::Quadrature<dim> &quadrature() const { return full; }

    private:
      /// int w dV over the locally owned cells, summed over ranks (current
      /// configuration); w = 1, or @p field of @p history.
      double integrate(const dealii::DoFHandler<dim> &dof_handler,
                       const dealii::Mapping<dim>    &mapping,
                       const HistoryStorage<dim>     *history,
                       const HistoryField             field) const;

      const material::RigidViscoplastic &material;
      const model::Kinematics<dim>      &kinematics;
      const dealii::Mapping<dim>        &reference_mapping;
      const material::DamageCriteria    *damage;
      dealii::QGauss<dim>                full;    // deviatoric part
      dealii::QGauss<dim>                reduced; // volumetric part
      bool product_form; // CellTangent::add_deviatoric, else add_general
    };
  } // namespace solver
} // namespace formsolve
