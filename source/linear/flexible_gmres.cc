#include <formsolve/linear/flexible_gmres.h>

#include <algorithm>
#include <cmath>

namespace formsolve
{
  namespace solver
  {
    using TrilinosVector = dealii::TrilinosWrappers::MPI::Vector;

    FlexibleGmres::FlexibleGmres(const Operator       &operator_vmult,
                                 TrilinosVector       &x,
                                 const TrilinosVector &b,
                                 const double          tolerance,
                                 const unsigned int    max_iterations,
                                 const unsigned int    max_basis)
        : vmult(operator_vmult)
        , x(x)
        , b(b)
        , tolerance(tolerance)
        , max_iterations(max_iterations)
        , m(std::max(1u, std::min(max_basis, max_iterations)))
        , v(m + 1)
        , z(m)
        , h(m, std::vector<double>(m + 1))
        , cs(m)
        , sn(m)
        , g(m + 1)
        , w(b)
    {
      // From x = 0 (most solves) the residual is b: no product with A.
      if (x.linfty_norm() > 0)
        {
          vmult(w, x);
          w.sadd(-1., 1., b);
        }
      residual = w.l2_norm();
      start_cycle();
    }

    void FlexibleGmres::start_cycle()
    {
      if (!(residual > tolerance && iterations < max_iterations))
        {
          done = true;
          return;
        }
      v[0].reinit(w, true);
      v[0].equ(1. / residual, w);
      std::fill(g.begin(), g.end(), 0.);
      g[0] = residual;
      k    = 0;
    }

    TrilinosVector &FlexibleGmres::preconditioned()
    {
      z[k].reinit(b, true);
      return z[k];
    }

    void FlexibleGmres::advance()
    {
      vmult(w, z[k]);
      ++iterations;
      // Modified Gram-Schmidt against v_0..v_k.
      auto &col = h[k];
      for (unsigned int i = 0; i <= k; ++i)
        {
          col[i] = w * v[i];
          w.add(-col[i], v[i]);
        }
      col[k + 1]             = w.l2_norm();
      const double next_norm = col[k + 1];
      for (unsigned int i = 0; i < k; ++i)
        {
          const double t = cs[i] * col[i] + sn[i] * col[i + 1];
          col[i + 1]     = -sn[i] * col[i] + cs[i] * col[i + 1];
          col[i]         = t;
        }
      const double r = std::hypot(col[k], col[k + 1]);
      cs[k]          = r > 0 ? col[k] / r : 1.;
      sn[k]          = r > 0 ? col[k + 1] / r : 0.;
      col[k]         = r;
      col[k + 1]     = 0;
      g[k + 1]       = -sn[k] * g[k];
      g[k]           = cs[k] * g[k];
      ++k;
      residual = std::abs(g[k]);
      // A zero next vector: the Krylov space holds the solution.
      if (residual <= tolerance || next_norm == 0 || k == m ||
          iterations == max_iterations)
        return finish_cycle();
      v[k].reinit(w, true);
      v[k].equ(1. / next_norm, w);
    }

    void FlexibleGmres::finish_cycle()
    {
      // y = R^-1 g, x += Z y.
      std::vector<double> y(k);
      for (int i = static_cast<int>(k) - 1; i >= 0; --i)
        {
          double s = g[i];
          for (unsigned int j = i + 1; j < k; ++j)
            s -= h[j][i] * y[j];
          y[i] = h[i][i] != 0 ? s / h[i][i] : 0.;
        }
      for (unsigned int j = 0; j < k; ++j)
        x.add(y[j], z[j]);
      if (residual <= tolerance)
        {
          done = true;
          return;
        }
      // Restart (or the last check): the true residual.
      vmult(w, x);
      w.sadd(-1., 1., b);
      residual = w.l2_norm();
      start_cycle();
    }

    FlexibleGmresResult FlexibleGmres::result() const
    {
      FlexibleGmresResult r;
      r.iterations = iterations;
      r.residual   = residual;
      r.converged  = residual <= tolerance;
      return r;
    }

    FlexibleGmresResult
    flexible_gmres(const FlexibleGmres::Operator &operator_vmult,
                   const FlexibleGmres::Operator &precondition,
                   TrilinosVector                &x,
                   const TrilinosVector          &b,
                   const double                   tolerance,
                   const unsigned int             max_iterations,
                   const unsigned int             max_basis)
    {
      FlexibleGmres gmres(operator_vmult,
                          x,
                          b,
                          tolerance,
                          max_iterations,
                          max_basis);
      while (!gmres.finished())
        {
          precondition(gmres.preconditioned(), gmres.direction());
          gmres.advance();
        }
      return gmres.result();
    }

    std::vector<FlexibleGmresResult>
    flexible_gmres_pair(const FlexibleGmres::Operator &operator_vmult,
                        const FlexibleGmres::Operator &precondition,
                        const PairPreconditioner      &precondition_pair,
                        TrilinosVector                &x0,
                        const TrilinosVector          &b0,
                        const double                   tolerance0,
                        const unsigned int             max_iterations0,
                        TrilinosVector                &x1,
                        const TrilinosVector          &b1,
                        const double                   tolerance1,
                        const unsigned int             max_iterations1)
    {
      FlexibleGmres first(operator_vmult, x0, b0, tolerance0, max_iterations0);
      FlexibleGmres second(operator_vmult, x1, b1, tolerance1, max_iterations1);
      while (!first.finished() || !second.finished())
        {
          if (!first.finished() && !second.finished())
            {
              precondition_pair(first.preconditioned(),
                                first.direction(),
                                second.preconditioned(),
                                second.direction());
              first.advance();
              second.advance();
            }
          else
            {
              FlexibleGmres &left = first.finished() ? second : first;
              precondition(left.preconditioned(), left.direction());
              left.advance();
            }
        }
      return {first.result(), second.result()};
    }
  } // namespace solver
} // namespace formsolve
