// The point of a step's Newton solve that was evaluated last: a line-search
// trial until Newton accepts it, then the iterate. Its contact pairs and
// their factors (keyed by the pairs) are the contact operator's; the search
// sees the tools at the point's speeds. The state's velocity, tools and
// contact set take the point's only when Newton accepts it. The one system
// matrix holds at most this point's tangent, assembled when first asked for.
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/newton/nonlinear_problem.h>

#include <vector>

namespace formsolve
{
  namespace solver
  {
    struct Iterate
    {
      /// What the system matrix holds of this point.
      enum class Matrix
      {
        /// Not its tangent: assembled when the body system is first read or
        /// the linear solve needs it.
        none,
        /// The body tangent K_b, which penalty estimates read.
        body,
        /// K_b + K_c, for the linear solve.
        body_and_contact
      };

      /// The sheet's velocity (mm/s, locally owned entries).
      dealii::TrilinosWrappers::MPI::Vector velocity;
      /// The velocities of the tools under force control (mm/s along each
      /// tool's direction, one per force equation).
      std::vector<double> tool_speeds;
      Linearisation       kind     = Linearisation::secant;
      bool                accepted = false;
      Matrix              matrix   = Matrix::none;

      bool has_tangent() const { return matrix != Matrix::none; }
    };
  } // namespace solver
} // namespace formsolve
