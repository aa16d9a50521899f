// The tools under force control (the blank holder with Control = force,
// additional tools with Motion = force): tool j's velocity u_j along its
// direction d_j is one more unknown of a step, with the equation
// rho_j = F_j,set - d_j . sum_k f_k = 0 over its pairs k (the force it
// exerts on the sheet along d_j equals the set force). With S_k = -df_k/dv
// of pair k (the tool's velocity enters as v_k - u_j d_j), Newton on (v, u)
// solves
//   K dv - B du = -r,   C^T dv - E du = -rho,
//   b_j = S d_j (= -dr/du_j),  c_j = d_j^T S (= drho_j/dv),
//   e_j = d_j^T S d_j (= -drho_j/du_j, >= 0),
// by elimination: K Y = -r and K Z = B with the same factors, then the
// m x m Schur complement (E - C^T Z) du = rho + C^T Y and dv = Y + Z du
// (doc/theory.md, section 6a). E is diagonal: a pair belongs to one tool.
// This class is those equations and their unknowns: the coupling terms, and
// u as it is accepted, tried along a line search and corrected.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/tools/tool_set.h>

#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class ForceEquations
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// The tools @p controlled (indices into the ToolSet) and vectors on
      /// the locally owned DoFs of the current mesh.
      void         reinit(const std::vector<unsigned int> &controlled,
                          const dealii::IndexSet          &owned,
                          const MPI_Comm                   comm);
      unsigned int size() const { return tools.size(); }
      unsigned int tool(const unsigned int j) const { return tools[j]; }

      /// A solve starts from the velocities @p u (mm/s along each
      /// direction); @p active: which equations hold (a released holder's
      /// does not; its tool stands).
      void begin_solve(const std::vector<double> &u,
                       const std::vector<bool>   &active);
      bool active(const unsigned int j) const { return on[j]; }
      bool any_active() const;
      /// The tools' velocities at step length @p alpha along the last
      /// correction (mm/s, one per equation).
      std::vector<double> speeds_at(const double alpha) const;
      /// Velocities @p speeds (from speeds_at()) are the iterate's.
      void accept(const std::vector<double> &speeds) { u = speeds; }
      /// The accepted velocity of equation j (mm/s).
      double velocity(const unsigned int j) const { return u[j]; }
      /// Moves the controlled tools at @p velocities.
      void move_tools(const std::vector<double> &velocities,
                      tools::ToolSet<dim>       &set) const;
      /// The velocities of all tools of @p set with the controlled ones at
      /// @p speeds (the set is not changed).
      std::vector<dealii::Tensor<1, dim>>
      tool_velocities(const std::vector<double> &speeds,
                      const tools::ToolSet<dim> &set) const;

      /// Coupling terms of the controlled tools' pairs at the current
      /// iterate. @p targets: the set forces on the modelled part (N).
      void assemble(const contact::ContactSet<dim>          &set,
                    const std::vector<double>               &epsilon,
                    const tools::ToolSet<dim>               &tools,
                    const double                             v0,
                    const double                             dt,
                    const bool                               newton,
                    const dealii::AffineConstraints<double> &constraints,
                    const std::vector<double>               &targets);

      /// rho_j (N): set force minus the force tool j exerts on the sheet.
      double residual(const unsigned int j) const { return rho[j]; }
      /// The column b_j of the bordered system (condensed).
      const VectorType &column(const unsigned int j) const { return b[j]; }
      /// Whether a pair of tool j carries force (else the system is
      /// singular in u_j and closing_correction() closes the gap instead).
      bool engaged(const unsigned int j) const { return has_contact[j]; }

      /// du_j for the engaged equations @p bordered from Y = K^-1 (-r) and
      /// z_i = K^-1 b_(bordered i); then dv = Y + sum du_j z_j. Each
      /// Schur diagonal is bounded below by 1e-8 e_j (see the .cc).
      void correct(const std::vector<unsigned int> &bordered,
                   const VectorType                &y,
                   const std::vector<VectorType>   &z);
      /// Equation j without a bordered correction: holds its velocity, or,
      /// without contact, the du_j that brings the nearest sheet node to
      /// penetration @p depth in this step.
      void
      hold_or_close(const unsigned int j, const double depth, const double dt);
      double correction(const unsigned int j) const { return du[j]; }

    private:
      std::vector<unsigned int> tools;
      std::vector<VectorType>   b, c;
      std::vector<double>       e, rho, u, du;
      std::vector<bool>         on, has_contact;
      // The nearest inactive pair of each tool: gap and d . n.
      std::vector<double> nearest_gap, nearest_dn;
    };
  } // namespace solver
} // namespace formsolve
