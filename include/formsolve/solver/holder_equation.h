// The blank holder under force control: its axial velocity w is one more
// unknown of a step, with the equation rho = F_set + sum_k f_k,z = 0 (the
// holder's contact force equals the set force). Newton on (v, w) solves the
// bordered system
//   [K   b] [dv]     [r  ]      b = dr/dw,  c = drho/dv,  e = drho/dw
//   [c^T e] [dw] = - [rho],
// by elimination with two solves of K (doc/theory.md, section 6a). This class
// is that equation and its unknown: the coupling terms, and w as it is
// accepted, tried along a line search and corrected.
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
    class HolderEquation
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// Vectors on the locally owned DoFs of the current mesh.
      void reinit(const dealii::IndexSet &owned, const MPI_Comm comm);

      /// A solve starts from the holder velocity @p w (mm/s).
      void begin_solve(const double w);
      /// The trial at step length @p alpha along the last correction.
      void set_step_length(const double alpha) { w_trial = w + alpha * dw; }
      /// The trial becomes the iterate.
      void accept() { w = w_trial; }
      /// The accepted and the trial velocity (mm/s).
      double velocity() const { return w; }
      double trial_velocity() const { return w_trial; }
      /// The correction of the next line search (mm/s).
      void   set_correction(const double d) { dw = d; }
      double last_correction() const { return dw; }

      /// Coupling terms of the holder pairs at the current iterate.
      /// @p target: the set force on the modelled part (N).
      void assemble(const contact::ContactSet<dim>          &set,
                    const std::vector<double>               &epsilon,
                    const tools::ToolSet<dim>               &tools,
                    const double                             v0,
                    const double                             dt,
                    const bool                               newton,
                    const dealii::AffineConstraints<double> &constraints,
                    const double                             target);

      /// rho (N): set force minus the holder's contact force.
      double residual() const { return rho; }
      /// The column b of the bordered system (condensed).
      const VectorType &column() const { return b; }
      /// Whether a holder pair carries force (else the system is singular in
      /// w and correction() closes the gap instead).
      bool engaged() const { return has_contact; }

      /// dw from y = K^-1 (-r) and z = K^-1 b; then dv = y - dw z. The Schur
      /// complement is bounded below by 1e-8 e (see the .cc).
      double correction(const VectorType &y, const VectorType &z) const;
      /// Without contact: the dw that brings the nearest sheet node to
      /// penetration @p depth in this step (mm/s).
      double closing_correction(const double depth, const double dt) const;

    private:
      VectorType b, c;
      double     e = 0, rho = 0;
      double     w = 0, w_trial = 0, dw = 0; // velocity (mm/s)
      bool       has_contact = false;
      double     nearest_gap = 0, nearest_nz = 1; // nearest inactive pair
    };
  } // namespace solver
} // namespace formsolve
