// Tangent and residual of the flow formulation with penalty contact.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/simulation/quadrature_history.h>
#include <formsolve/tools/tool_set.h>

namespace formsolve
{
  namespace solver
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;
    using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

    template <int dim>
    using HistoryStorage = dealii::CellDataStorage<
      typename dealii::Triangulation<dim>::cell_iterator,
      simulation::QuadraturePointHistory>;

    /// Contact data the assembler reads: pairs, their factors, and the law.
    template <int dim>
    struct ContactInput
    {
      const contact::ContactSet<dim> *set                     = nullptr;
      const std::vector<double>      *epsilon                 = nullptr;
      const tools::ToolSet<dim>      *tools                   = nullptr;
      double                          regularisation_velocity = 1e-3;
    };

    template <int dim>
    class Assembler
    {
    public:
      /// @p reference_mapping maps the initial configuration: the volumetric
      /// term drives each cell back to its initial volume (doc/theory.md).
      Assembler(const material::RigidViscoplastic<dim> &material,
                const dealii::Mapping<dim>             &reference_mapping,
                const unsigned int                      degree);

      /// Residual r = f_int - f_contact (and the tangent if @p matrix is not
      /// null) at velocity @p v (ghosted), geometry given by @p mapping.
      /// Returns the norm of the internal nodal forces, a scale for |r|.
      double assemble(const dealii::DoFHandler<dim>           &dof_handler,
                      const dealii::Mapping<dim>              &mapping,
                      const dealii::AffineConstraints<double> &constraints,
                      const VectorType                        &v,
                      const HistoryStorage<dim>               &history,
                      const double                             dt,
                      const ContactInput<dim>                 &contact,
                      const bool                               newton,
                      MatrixType                              *matrix,
                      VectorType                              &residual) const;

      /// The body part of assemble(): cells only, matrix and residual
      /// zeroed first and compressed at the end.
      double assemble_body(const dealii::DoFHandler<dim>           &dof_handler,
                           const dealii::Mapping<dim>              &mapping,
                           const dealii::AffineConstraints<double> &constraints,
                           const VectorType                        &v,
                           const HistoryStorage<dim>               &history,
                           const double                             dt,
                           const bool                               newton,
                           MatrixType                              *matrix,
                           VectorType &residual) const;

      /// The contact part of assemble(): adds the nodal contact forces and
      /// stiffnesses of the active pairs, then compresses.
      void add_contact(const dealii::AffineConstraints<double> &constraints,
                       const double                             dt,
                       const ContactInput<dim>                 &contact,
                       const bool                               newton,
                       MatrixType                              *matrix,
                       VectorType                              &residual) const;

      /// After convergence: integrate strain, thickness strain, store stresses.
      void update_history(const dealii::DoFHandler<dim> &dof_handler,
                          const dealii::Mapping<dim>    &mapping,
                          const VectorType              &v,
                          const double                   dt,
                          HistoryStorage<dim>           &history) const;

      /// Create history entries on the locally owned cells.
      void initialize_history(const dealii::DoFHandler<dim> &dof_handler,
                              HistoryStorage<dim>           &history) const;

      /// Volume of the body in the configuration given by @p mapping (mm^3).
      double volume(const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping) const;

      /// Volume integral of the equivalent plastic strain (mm^3), current
      /// configuration: what refinement must carry over.
      double strain_integral(const dealii::DoFHandler<dim> &dof_handler,
                             const dealii::Mapping<dim>    &mapping,
                             const HistoryStorage<dim>     &history) const;

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
      /// configuration); w = 1, or the equivalent strain of @p history.
      double integrate(const dealii::DoFHandler<dim> &dof_handler,
                       const dealii::Mapping<dim>    &mapping,
                       const HistoryStorage<dim>     *history) const;

      /// tr(D) + ln(J/J0)/dt at the reduced quadrature points of @p cell:
      /// the volumetric rate with the accumulated volume error corrected.
      template <typename Iterator>
      void volumetric_rates(const Iterator        &cell,
                            dealii::FEValues<dim> &current,
                            dealii::FEValues<dim> &initial,
                            const VectorType      &v,
                            const double           dt,
                            std::vector<double>   &rates) const;

      const material::RigidViscoplastic<dim> &material;
      const dealii::Mapping<dim>             &reference_mapping;
      dealii::QGauss<dim>                     full;    // deviatoric part
      dealii::QGauss<dim>                     reduced; // volumetric part
    };
  } // namespace solver
} // namespace formsolve
