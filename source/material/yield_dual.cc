#include <deal.II/base/exceptions.h>

#include <formsolve/material/yield_dual.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    void DualStatistics::add(const unsigned int n)
    {
      ++solves;
      iterations += n;
      long_solves += n > 6;
      most = std::max(most, n);
    }

    namespace
    {
      /// (H + P_h)^-1 - P_h with P_h = I (x) I / 3: the inverse of H on
      /// deviators, H having the identity in its null space.
      SymmetricTensor<4, 3> deviatoric_inverse(const SymmetricTensor<4, 3> &H)
      {
        static const SymmetricTensor<4, 3> Ph =
          outer_product(unit_symmetric_tensor<3>(),
                        unit_symmetric_tensor<3>()) /
          3.;
        return invert(H + Ph) - Ph;
      }

      [[noreturn]] void fail(const SymmetricTensor<2, 3> &e,
                             const double                 residual)
      {
        std::ostringstream m;
        m << "Yld2004-18p: the stress of the strain-rate deviator (" << e
          << ") in the orthotropy frame was not found by 50 Newton "
             "iterations or a line search (relative residual "
          << residual
          << "); the coefficients may not give a strictly convex yield "
             "function (Material/Yld2004-18p C1, C2)";
        AssertThrow(false, ExcMessage(m.str()));
        throw;
      }
    } // namespace

    DualPoint solve_dual(const Yld2004               &f,
                         const SymmetricTensor<2, 3> &e_in,
                         const SymmetricTensor<2, 3> *start)
    {
      DualPoint                   out;
      const SymmetricTensor<2, 3> e0 = deviator(e_in);
      const double                n  = e0.norm();
      if (n == 0)
        {
          out.compliance = deviatoric_inverse(f.half_square(e0).hessian);
          return out;
        }
      // Homogeneity: solve for the unit rate, scale s by n at the end.
      const SymmetricTensor<2, 3> e = e0 / n;
      // The start's direction (von Mises's without one) at the multiple t
      // minimising t^2 g - t s:e; a start against e is no start.
      SymmetricTensor<2, 3> s = (2. / 3.) * e;
      if (start && deviator(*start) * e > 0)
        s = deviator(*start);
      // g is of degree 2: scaling s by t scales g by t^2, its gradient by
      // t and leaves its Hessian.
      auto         g = f.half_square(s);
      const double t = (s * e) / (2 * g.value);
      s *= t;
      g.value *= t * t;
      g.gradient *= t;
      double       objective = g.value - s * e;
      unsigned int it        = 0;
      for (;; ++it)
        {
          const SymmetricTensor<2, 3> r    = g.gradient - e;
          const double                norm = r.norm();
          if (norm <= 1e-13)
            break;
          if (it == 50)
            fail(e0, norm);
          SymmetricTensor<2, 3> step = -(deviatoric_inverse(g.hessian) * r);
          // Where the surface is nearly flat (large exponents, a start on a
          // flat face) the Newton step is huge: no longer than s itself.
          if (step.norm() > s.norm())
            step *= s.norm() / step.norm();
          // Backtracking on the convex objective g(s) - s : e; near the
          // solution its decrease (residual squared) drowns in rounding,
          // and a smaller residual accepts the step instead.
          double alpha    = 1;
          bool   accepted = false;
          for (unsigned int k = 0; k < 30 && !accepted; ++k, alpha *= 0.5)
            {
              const auto   trial = f.half_square(s + alpha * step);
              const double value = trial.value - (s + alpha * step) * e;
              accepted = value <= objective + 1e-4 * alpha * (r * step) ||
                         (trial.gradient - e).norm() < 0.5 * norm;
              if (accepted)
                {
                  s += alpha * step;
                  g         = trial;
                  objective = value;
                }
            }
          // Nothing better within rounding of the eigenvalues: converged;
          // nothing better far from it: the same step would follow.
          if (!accepted && norm <= 1e-10)
            break;
          if (!accepted)
            fail(e0, norm);
        }
      out.iterations = it;
      out.stress     = n * s;
      out.rate       = n * std::sqrt(2 * g.value);
      out.compliance = deviatoric_inverse(g.hessian);
      return out;
    }
  } // namespace material
} // namespace formsolve
