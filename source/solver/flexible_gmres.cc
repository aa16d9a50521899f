#include <formsolve/solver/flexible_gmres.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace formsolve
{
  namespace solver
  {
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    FlexibleGmresResult flexible_gmres(
      const std::function<void(Vector &, const Vector &)> &operator_vmult,
      const std::function<void(Vector &, const Vector &)> &precondition,
      Vector                                              &x,
      const Vector                                        &b,
      const double                                         tolerance,
      const unsigned int                                   max_iterations,
      const unsigned int                                   max_basis)
    {
      FlexibleGmresResult result;
      const unsigned int  m = std::max(1u, std::min(max_basis, max_iterations));
      std::vector<Vector> v(m + 1), z(m);
      // Hessenberg columns after the Givens rotations (upper triangle R),
      // the rotations, and the rotated right-hand side g.
      std::vector<std::vector<double>> h(m, std::vector<double>(m + 1));
      std::vector<double>              cs(m), sn(m), g(m + 1);
      Vector                           w(b);

      // From x = 0 (most solves) the residual is b: no product with A.
      if (x.linfty_norm() > 0)
        {
          operator_vmult(w, x);
          w.sadd(-1., 1., b);
        }
      result.residual = w.l2_norm();
      while (result.residual > tolerance && result.iterations < max_iterations)
        {
          const double beta = result.residual;
          v[0].reinit(w, true);
          v[0].equ(1. / beta, w);
          std::fill(g.begin(), g.end(), 0.);
          g[0]           = beta;
          unsigned int k = 0; // columns in this cycle
          while (k < m && result.iterations < max_iterations)
            {
              z[k].reinit(b, true);
              precondition(z[k], v[k]);
              operator_vmult(w, z[k]);
              ++result.iterations;
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
              result.residual = std::abs(g[k]);
              // A zero next vector: the Krylov space holds the solution.
              if (result.residual <= tolerance || next_norm == 0)
                break;
              v[k].reinit(w, true);
              v[k].equ(1. / next_norm, w);
            }
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
          if (result.residual <= tolerance)
            break;
          // Restart (or the last check): the true residual.
          operator_vmult(w, x);
          w.sadd(-1., 1., b);
          result.residual = w.l2_norm();
        }
      result.converged = result.residual <= tolerance;
      return result;
    }
  } // namespace solver
} // namespace formsolve
