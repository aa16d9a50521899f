// The springback release (doc/theory.md, section 12): the tools are gone,
// the part is held by its supports, and the end-of-forming stress is
// released on the deformed mesh. Newton on the displacement u of
// int B^T sigma(u) dV - g = 0 with sigma = the release law's (elastic on top
// of the end stress, returned to the yield surface where it would leave it):
// one linear solve when no point yields again. g is the end stress's own
// imbalance in the release's space, int B^T sigma_end dV minus the tools'
// forces: the forming balanced its stress against its own element's test
// functions only, and a release of higher degree must not see the
// difference as a load (eq. 12c).
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <formsolve/material/release_law.h>
#include <formsolve/springback/end_load.h>
#include <formsolve/springback/end_state.h>
#include <formsolve/springback/supports.h>
#include <formsolve/trimming/trim_cells.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace formsolve
{
  namespace springback
  {
    /// What the release found (all ranks).
    struct ReleaseSummary
    {
      unsigned int iterations     = 0; // Newton (linear solves)
      double       released_force = 0; // |int B^T sigma_end dV| (N)
      double       residual       = 0; // last |r| / released_force
      /// |g| / |int B^T sigma_end dV|: how far the end stress is from the
      /// release space's equilibrium with the tools' forces (0 without
      /// them).
      double imbalance        = 0;
      double max_displacement = 0; // mm
      double volume           = 0; // mm^3, the modelled part
      /// Volume fractions: yielding again in the release; strained less
      /// than Sound strain ratio yield strains; rigid in the last step
      /// (rate below 10 times the Limiting strain rate).
      double yielded_fraction = 0, small_strain_fraction = 0,
             rigid_fraction          = 0;
      double      max_trial_ratio    = 0; // sigma_bar_trial / sigma_y, largest
      double      max_plastic_strain = 0; // of the release
      std::string supports;               // where the part is held, in words
    };

    /// Springback/Element degree, or the forming's if 0.
    template <int dim>
    unsigned int release_degree(const state::State<dim> &state);

    template <int dim>
    class Release
    {
    public:
      /// The release of @p state's end of forming; throws naming
      /// Springback/Supports when they leave a rigid-body motion free.
      /// @p end_forces: the forming's internal forces at its converged last
      /// step (on the state's DoFs), which the tools balanced; if nullptr,
      /// the release takes the whole int B^T sigma_end dV as the load
      /// (g = 0).
      /// @p configuration: where the last step found its equilibrium (its
      /// start), on which the end stress and forces are evaluated and the
      /// release is solved.
      /// @p kept: the trimmed part (nullptr, or no cell cut away: the whole
      /// part); the release is solved on these cells and loaded by their
      /// own end stress, int_part B^T sigma_end dV, which holds the tools'
      /// forces and the traction of the cells cut away (eq. 13a);
      /// @p end_forces are not used then.
      Release(const state::State<dim>           &state,
              const dealii::Mapping<dim>        &configuration,
              const material::RigidViscoplastic &material,
              const material::ReleaseLaw        &law,
              const VectorType                  *end_forces,
              const trimming::KeptCells         *kept = nullptr);

      /// Solves; throws if Newton does not reach Springback/Tolerance.
      ReleaseSummary solve();

      /// The release's element on every cell of the mesh; the displacement
      /// is 0 on cells cut away.
      const dealii::DoFHandler<dim> &dof_handler() const { return dh; }
      /// Whether a cell (of any DoFHandler on the state's mesh) belongs to
      /// the part released: every locally owned or ghost cell when the part
      /// is not trimmed.
      template <class Iterator>
      bool in_part(const Iterator &cell) const
      {
        return !kept || (*kept)[cell->active_cell_index()];
      }
      /// Whether cells were cut away (on any rank).
      bool trimmed() const { return kept != nullptr; }
      /// The springback displacement (ghosted) and its owned copy.
      const VectorType &displacement() const { return u_ghost; }
      const VectorType &owned_displacement() const { return u_full; }
      /// Per active cell (locally owned): the residual stress's mean over
      /// the cell, its equivalent stress (the criterion's) and the
      /// end-of-forming one (MPa), and the cell's volume fraction that
      /// yielded again.
      const dealii::Vector<float> &residual_equivalent() const
      {
        return cell_residual;
      }
      const dealii::Vector<float> &end_equivalent() const { return cell_end; }
      const dealii::Vector<float> &residual_mean() const { return cell_mean; }
      /// The cell mean of the residual stress's component @p k (MPa), k in
      /// SymmetricTensor<2, 3>'s unrolled order (00, 11, 22, 01, 02, 12) of
      /// the kinematics' frame.
      const dealii::Vector<float> &residual_stress(const unsigned int k) const
      {
        return cell_stress[k];
      }
      const dealii::Vector<float> &yielded() const { return cell_yielded; }

    private:
      void setup();
      /// Residual and (with @p matrix) tangent at u; fills the cell fields
      /// and the point statistics of @p s.
      double assemble(const bool matrix, ReleaseSummary &s);
      /// The statistics of the end state alone.
      void measure_end_state(ReleaseSummary &s) const;
      /// The displacement on dh from the part's.
      void spread_displacement();

      const state::State<dim>    &state;
      const dealii::Mapping<dim> &mapping;
      const material::ReleaseLaw &law;
      const parameters::Run      &prm;
      dealii::FESystem<dim>       fe;
      /// fe on the part's cells, nothing on those cut away.
      dealii::hp::FECollection<dim> part_fe;
      dealii::QGauss<dim>           quadrature;
      dealii::DoFHandler<dim>       dh, part;
      const trimming::KeptCells    *kept;
      /// The part's: hanging nodes, symmetry planes, supports.
      dealii::AffineConstraints<double>      constraints;
      EndState<dim>                          end;
      std::vector<Support<dim>>              supports;
      dealii::TrilinosWrappers::SparseMatrix matrix;
      const VectorType                      *end_forces;
      /// On the part's DoFs, except u_ghost and u_full (dh's).
      VectorType            u, residual, defect, u_ghost, u_full;
      VectorType            part_ghost; // u, ghosted
      dealii::Vector<float> cell_residual, cell_end, cell_mean, cell_yielded;
      std::array<dealii::Vector<float>, 6> cell_stress;
    };
  } // namespace springback
} // namespace formsolve
