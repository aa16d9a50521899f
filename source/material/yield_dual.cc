#include <deal.II/base/exceptions.h>

#include <formsolve/material/yield_dual.h>

#include <Eigen/Dense>

#include <algorithm>
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
      using Matrix6 = Eigen::Matrix<double, 6, 6>;
      using Vector6 = Eigen::Matrix<double, 6, 1>;

      double dot(const Mandel6 &a, const Mandel6 &b)
      {
        double d = 0;
        for (unsigned int r = 0; r < 6; ++r)
          d += a[r] * b[r];
        return d;
      }

      /// H + P_h, P_h = I (x) I / 3 in Mandel's notation: positive definite
      /// for a strictly convex g, whose Hessian has the identity in its null
      /// space.
      Matrix6 completed(const Mandel6x6 &H)
      {
        Matrix6 A;
        for (unsigned int r = 0; r < 6; ++r)
          for (unsigned int c = 0; c < 6; ++c)
            A(r, c) = H[r][c] + (r < 3 && c < 3 ? 1. / 3. : 0.);
        return A;
      }

      /// (H + P_h)^-1 B by Cholesky; by LDL^T where rounding leaves H + P_h
      /// not quite positive definite (a nearly flat surface).
      template <typename Rhs>
      auto completed_solve(const Mandel6x6 &H, const Rhs &B)
      {
        const Matrix6 A = completed(H);
        const auto    c = A.llt();
        return c.info() == Eigen::Success ? Rhs(c.solve(B))
                                          : Rhs(A.ldlt().solve(B));
      }

      /// (H + P_h)^-1 - P_h: the inverse of H on deviators.
      Mandel6x6 deviatoric_inverse(const Mandel6x6 &H)
      {
        const Matrix6 inverse = completed_solve(H, Matrix6::Identity().eval());
        Mandel6x6     C;
        for (unsigned int r = 0; r < 6; ++r)
          for (unsigned int c = 0; c < 6; ++c)
            C[r][c] = inverse(r, c) - (r < 3 && c < 3 ? 1. / 3. : 0.);
        return C;
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

      /// The Newton step -(H + P_h)^-1 r on deviators (r is one), no
      /// longer than @p s: where the surface is nearly flat (large
      /// exponents, a start on a flat face) the step is huge.
      Mandel6
      newton_step(const Mandel6x6 &H, const Mandel6 &r, const Mandel6 &s)
      {
        Vector6 b;
        for (unsigned int k = 0; k < 6; ++k)
          b(k) = -r[k];
        const Vector6 x      = completed_solve(H, b);
        const double  factor = std::min(1., std::sqrt(dot(s, s)) / x.norm());
        Mandel6       step;
        for (unsigned int k = 0; k < 6; ++k)
          step[k] = factor * x(k);
        return step;
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
          out.compliance = deviatoric_inverse(f.half_square(Mandel6{}).hessian);
          return out;
        }
      // Homogeneity: solve for the unit rate, scale s by n at the end. All
      // in Mandel's notation, whose dot product is the tensors'.
      const Mandel6 e = to_mandel(e0 / n);
      // The start's direction (von Mises's without one) at the multiple t
      // minimising t^2 g - t s:e; a start against e is no start.
      Mandel6 s = to_mandel((2. / 3.) * (e0 / n));
      if (start && deviator(*start) * e0 > 0)
        s = to_mandel(deviator(*start));
      // g is of degree 2: scaling s by t scales g by t^2, its gradient by
      // t and leaves its Hessian.
      auto         g = f.half_square(s);
      const double t = dot(s, e) / (2 * g.value);
      for (unsigned int k = 0; k < 6; ++k)
        s[k] *= t, g.gradient[k] *= t;
      g.value *= t * t;
      double       objective = g.value - dot(s, e);
      unsigned int it        = 0;
      for (;; ++it)
        {
          Mandel6 r;
          for (unsigned int k = 0; k < 6; ++k)
            r[k] = g.gradient[k] - e[k];
          const double norm = std::sqrt(dot(r, r));
          if (norm <= 1e-13)
            break;
          if (it == 50)
            fail(e0, norm);
          const Mandel6 step = newton_step(g.hessian, r, s);
          // Backtracking on the convex objective g(s) - s : e; near the
          // solution its decrease (residual squared) drowns in rounding,
          // and a smaller residual accepts the step instead.
          double alpha    = 1;
          bool   accepted = false;
          for (unsigned int k = 0; k < 30 && !accepted; ++k, alpha *= 0.5)
            {
              Mandel6 x = s;
              for (unsigned int j = 0; j < 6; ++j)
                x[j] += alpha * step[j];
              const auto   trial = f.half_square(x);
              const double value = trial.value - dot(x, e);
              Mandel6      rt;
              for (unsigned int j = 0; j < 6; ++j)
                rt[j] = trial.gradient[j] - e[j];
              accepted = value <= objective + 1e-4 * alpha * dot(r, step) ||
                         std::sqrt(dot(rt, rt)) < 0.5 * norm;
              if (accepted)
                {
                  s         = x;
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
      out.stress     = n * from_mandel(s);
      out.rate       = n * std::sqrt(2 * g.value);
      out.compliance = deviatoric_inverse(g.hessian);
      return out;
    }
  } // namespace material
} // namespace formsolve
