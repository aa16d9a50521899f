// The stress direction of a non-quadratic yield function for a given rate of
// deformation (doc/theory.md, eq. 3e): with g = sigma_bar^2/2, homogeneous
// of degree 2, the deviatoric s that minimises g(s) - s : D' solves
// grad g(s) = D' (normality), and then eps_bar_dot = sigma_bar(s) and
// sigma' = (sigma_flow/eps_bar_dot) s. A guarded Newton method per point:
// a von Mises start scaled to the best multiple, backtracking on the convex
// objective, a bounded number of iterations and an error naming the rate
// where it fails.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/yld2004.h>

namespace formsolve
{
  namespace material
  {
    struct DualPoint
    {
      SymmetricTensor<2, 3> stress;   // s: grad g(s) = D'
      double                rate = 0; // sigma_bar(s) = eps_bar_dot
      // ds/dD' = (grad^2 g)^+, the pseudo-inverse on deviators, in
      // Mandel's notation.
      Mandel6x6    compliance{};
      unsigned int iterations = 0;
    };

    /// Counts of the local solves of this process (the run summary's
    /// "local Newton" line): solves, their iterations, the most any took,
    /// and how many needed more than 6.
    struct DualStatistics
    {
      unsigned long solves = 0, iterations = 0, long_solves = 0;
      unsigned int  most = 0;
      void          add(const unsigned int n);
    };

    /// @p e: a deviatoric rate of deformation in the orthotropy frame;
    /// @p start: a stress direction to start from (the point's solution at
    /// the last accepted iterate), or nullptr for von Mises's.
    DualPoint solve_dual(const Yld2004               &f,
                         const SymmetricTensor<2, 3> &e,
                         const SymmetricTensor<2, 3> *start = nullptr);
  } // namespace material
} // namespace formsolve
