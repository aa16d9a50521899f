// The equivalent draw beads as terms of a step's system (doc/theory.md,
// section 6d). At the start of a step each bead's points are found on the
// sheet's die-side and holder-side faces (half of the line force on each,
// so that it bends nothing), and the bead's penetration there sets the line
// forces. At every evaluation the bead pulls on the material crossing it:
// t = -F reg(v.n) n per unit length, n across the line, regularised as
// friction is (its tangent alike); the opening force is taken from the
// holder's set force. Nothing here is gathered across ranks beyond the
// beads' own points.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/beads/bead_line.h>
#include <formsolve/beads/bead_model.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/state/state.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace beads
  {
    template <int dim>
    class BeadOperator
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;
      using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

      BeadOperator(const parameters::Run             &prm,
                   const material::RigidViscoplastic &law,
                   const model::Kinematics<dim>      &kinematics);

      bool any() const { return !lines.empty(); }
      /// A step begins on the state's current mesh and tool positions:
      /// where the lines cross the sheet, and the line forces there.
      void begin_step(const state::State<dim> &state);
      /// Throws naming the bead where a point of its line in the modelled
      /// part lies off the blank, or off the die's or the holder's face
      /// (at the start of the run; the same on every rank).
      void check_scene(const state::State<dim> &state);
      /// One sentence per bead: its forces per unit length at full
      /// penetration and where they come from.
      std::vector<std::string> describe() const;
      /// run-summary.txt lines of each bead, with what @p records say it
      /// did, scaled to the full part by @p symmetry.
      std::string summary_lines(const std::vector<state::BeadRecord> &records,
                                const double symmetry) const;
      /// The beads' opening force on the modelled part (N).
      double opening() const { return opening_force; }
      /// Adds the beads' terms at the velocity @p v (ghosted) to @p r
      /// and/or @p K (either may be null); @p v0 regularises as friction's.
      void add(const VectorType                        &v,
               const dealii::AffineConstraints<double> &constraints,
               const double                             v0,
               const bool                               newton,
               MatrixType                              *K,
               VectorType                              *r) const;
      /// Each bead's force, opening, power and drawn rate at @p v (modelled
      /// part); every rank.
      std::vector<state::BeadRecord>
      rates(const VectorType &v, const double v0, const MPI_Comm comm) const;

    private:
      /// A point of a line on a face of a locally owned cell.
      struct Hit
      {
        unsigned int bead, point;
        double       share; // of the point's line force on this face
        std::vector<dealii::types::global_dof_index> dofs;
        std::vector<double> g; // v . n at the point = g . v_cell
      };
      /// The sheet's faces toward @p side (-1 die, +1 holder) that the
      /// lines' points lie on, with the tool's clearance at each point.
      void locate(const state::State<dim>          &state,
                  const int                         side,
                  std::vector<Hit>                 &found,
                  std::vector<std::vector<double>> &clearance,
                  std::vector<std::vector<double>> &count) const;
      /// The line forces of bead @p b at its points from the clearances.
      void   set_forces(const unsigned int                      b,
                        const std::vector<std::vector<double>> &clear,
                        const std::vector<std::vector<double>> &count);
      double v_normal(const Hit &h, const VectorType &v) const;
      /// Restraining and opening force per length of bead @p b at full
      /// penetration, at the line's start (N/mm).
      BeadForces full_forces(const unsigned int b) const;

      const parameters::DrawBeads             &params;
      std::vector<std::vector<BeadPoint<dim>>> lines;
      std::vector<double> sigma_ps; // per bead, MPa (Model = geometry)
      double              t0;
      std::vector<Hit>    hits;
      /// Per bead and point: restraining and opening force (N/mm), and
      /// whether the point lies on the sheet.
      std::vector<std::vector<double>> force, open, on_sheet;
      double                           opening_force = 0;
    };
  } // namespace beads
} // namespace formsolve
