#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/physics/notation.h>

#include <formsolve/material/directional.h>
#include <formsolve/material/yield_fit.h>
#include <formsolve/material/yld2004.h>
#include <formsolve/parameters/anisotropy.h>

#include <Eigen/Dense>
#include <boost/math/tools/roots.hpp>

#include <array>
#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    namespace
    {
      /// C P_dev for c12, c13, c21, c23, c31, c32, c44, c55, c66.
      SymmetricTensor<4, 3> transformation(const std::vector<double> &c)
      {
        AssertDimension(c.size(), 9);
        SymmetricTensor<4, 3> C;
        C[0][0][1][1] = -c[0];
        C[0][0][2][2] = -c[1];
        C[1][1][0][0] = -c[2];
        C[1][1][2][2] = -c[3];
        C[2][2][0][0] = -c[4];
        C[2][2][1][1] = -c[5];
        // C : s counts each shear entry twice: (C : s)_23 = c44 s_23.
        C[1][2][1][2] = c[6] / 2;
        C[0][2][0][2] = c[7] / 2;
        C[0][1][0][1] = c[8] / 2;
        return C * deviator_tensor<3>();
      }

      /// The upper triangle of H += c u u^T.
      void add_outer(Mandel6x6 &H, const double c, const Mandel6 &u)
      {
        for (unsigned int r = 0; r < 6; ++r)
          {
            const double cu = c * u[r];
            for (unsigned int s = r; s < 6; ++s)
              H[r][s] += cu * u[s];
          }
      }
      /// The upper triangle of H += c (u v^T + v u^T).
      void add_outer(Mandel6x6     &H,
                     const double   c,
                     const Mandel6 &u,
                     const Mandel6 &v)
      {
        for (unsigned int r = 0; r < 6; ++r)
          {
            const double cu = c * u[r], cv = c * v[r];
            for (unsigned int s = r; s < 6; ++s)
              H[r][s] += cu * v[s] + cv * u[s];
          }
      }

      /// |x|^(a-2), by products for whole exponents (the usual 6, 8).
      double power(const double x, const double p)
      {
        if (p == std::floor(p) && p <= 40)
          {
            double y = 1;
            for (int k = 0; k < int(p); ++k)
              y *= x;
            return y;
          }
        return std::pow(x, p);
      }


      /// The eigenpairs of a symmetric 3x3 matrix: Eigen's closed form
      /// (the cubic's roots, eigenvectors by cross products) where the
      /// eigenvalues lie apart, deal.II's QL iteration where two come
      /// within 5 % of their spread. The closed form's error grows as
      /// 1e-15 over the relative gap: within 2e-14 here, as the local
      /// solve's 1e-13 needs; twice as fast as QL.
      std::array<std::pair<double, Tensor<1, 3>>, 3>
      eigenpairs(const SymmetricTensor<2, 3> &X)
      {
        Eigen::Matrix3d A;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            A(i, j) = X[i][j];
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(A);
        const auto  &l      = solver.eigenvalues(); // ascending
        const double spread = l(2) - l(0);
        if (!(spread > 0) || l(1) - l(0) < 0.05 * spread ||
            l(2) - l(1) < 0.05 * spread)
          return eigenvectors(X);
        std::array<std::pair<double, Tensor<1, 3>>, 3> pairs;
        for (unsigned int i = 0; i < 3; ++i)
          {
            pairs[i].first = l(i);
            for (unsigned int k = 0; k < 3; ++k)
              pairs[i].second[k] = solver.eigenvectors()(k, i);
          }
        return pairs;
      }

      /// The eigenpairs of one transformed stress and what the Hessian of
      /// sum_i h(lambda_i) needs of them (Daleckii-Krein).
      struct Spectrum
      {
        std::array<double, 3> lambda;
        // Pulled back to the stress by the transformation L: L^T v_i (x)
        // v_i, and L^T sym(v_i (x) v_k) for the pairs 01, 02, 12 (6-vectors).
        std::array<Mandel6, 3> P, S;
        Spectrum(const SymmetricTensor<2, 3> &X, const Mandel6x6 &L)
        {
          const auto e = eigenpairs(X);
          // L^T sym(u (x) v) with sym(u (x) v) written in Mandel's order.
          const auto pulled = [&L](const Tensor<1, 3> &u,
                                   const Tensor<1, 3> &v) {
            const double  h = M_SQRT1_2;
            const Mandel6 m = {{u[0] * v[0],
                                u[1] * v[1],
                                u[2] * v[2],
                                h * (u[1] * v[2] + u[2] * v[1]),
                                h * (u[0] * v[2] + u[2] * v[0]),
                                h * (u[0] * v[1] + u[1] * v[0])}};
            return transpose_multiply(L, m);
          };
          for (unsigned int i = 0; i < 3; ++i)
            {
              lambda[i] = e[i].first;
              P[i]      = pulled(e[i].second, e[i].second);
            }
          const unsigned int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
          for (unsigned int p = 0; p < 3; ++p)
            S[p] = pulled(e[pairs[p][0]].second, e[pairs[p][1]].second);
        }
      };
    } // namespace

    Yld2004::Yld2004(const std::vector<double> &c1,
                     const std::vector<double> &c2,
                     const double               exponent)
        : L1(transformation(c1))
        , L2(transformation(c2))
        , M1(to_mandel(L1))
        , M2(to_mandel(L2))
        , a(exponent)
    {
      scale = 1 / equivalent(uniaxial_stress(0));
    }

    Yld2004 Yld2004::hosford(const double exponent)
    {
      const std::vector<double> ones(9, 1.);
      return Yld2004(ones, ones, exponent);
    }

    Yld2004 Yld2004::from_parameters(const parameters::Anisotropy &p)
    {
      const bool fitted =
        p.criterion == parameters::YieldCriterion::yld2004_18p &&
        p.yld_source == parameters::YldCoefficients::fitted;
      const YldFit fit = fitted ? fit_yld2004(p) : YldFit();
      Yld2004      f(fitted ? fit.c1 : p.yld_coefficients(1),
                fitted ? fit.c2 : p.yld_coefficients(2),
                p.yield_exponent);
      if (fitted)
        {
          f.fit_report = fit.report;
          f.headline   = fit.headline;
        }
      const std::string entries =
        fitted ? "The Yld2004-18p set fitted to Material/Yld2004-18p fit"
               : "Material/Yld2004-18p C1, C2";
      AssertThrow(std::isfinite(f.scale) && f.scale > 0,
                  ExcMessage(entries + " give no yield stress in uniaxial "
                                       "tension along RD"));
      const SymmetricTensor<2, 3> s = f.least_convex();
      if (s.norm() > 0)
        {
          std::ostringstream m;
          m << entries << " (with Yield exponent = " << p.yield_exponent
            << ") give a yield function that is not strictly convex: its "
               "curvature vanishes at the deviatoric stress direction ("
            << s << "); the flow rule has no unique stress there";
          AssertThrow(false, ExcMessage(m.str()));
        }
      return f;
    }

    SymmetricTensor<2, 3> Yld2004::least_convex() const
    {
      // Directions spread over the unit sphere of deviators by a low-
      // discrepancy sequence; the Hessian of g plus the hydrostatic
      // projector must be positive definite at each.
      const SymmetricTensor<4, 3> Ph =
        outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>()) /
        3.;
      for (unsigned int k = 1; k <= 500; ++k)
        {
          SymmetricTensor<2, 3> s;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              s[i][j] =
                std::cos(k * (0.6180339887 + 0.4142135624 * (3 * i + j)) +
                         2.0 * (3 * i + j));
          s = deviator(s);
          if (s.norm() < 1e-6)
            continue;
          LAPACKFullMatrix<double> H(6, 6);
          H = Physics::Notation::Kelvin::to_matrix(half_square(s).hessian + Ph);
          H.compute_eigenvalues();
          for (unsigned int i = 0; i < 6; ++i)
            if (!(H.eigenvalue(i).real() > 1e-8))
              return s / s.norm();
        }
      return SymmetricTensor<2, 3>();
    }

    double Yld2004::phi(const SymmetricTensor<2, 3> &sigma,
                        Mandel6                     *gradient,
                        Mandel6x6                   *hessian) const
    {
      const Spectrum s1(L1 * sigma, M1), s2(L2 * sigma, M2);
      // f(x) = |x|^a and its derivatives at the differences d_ij.
      double f = 0, f1[3][3], f2[3][3];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const double d = s1.lambda[i] - s2.lambda[j], x = std::abs(d);
            const double p = power(x, a - 2);
            f += p * x * x;
            f1[i][j] = a * p * d;
            f2[i][j] = a * (a - 1) * p;
          }
      if (!gradient)
        return f;

      std::array<double, 3> g1{}, g2{}, h1{}, h2{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            g1[i] += f1[i][j];
            g2[j] -= f1[i][j];
            h1[i] += f2[i][j];
            h2[j] += f2[i][j];
          }
      Mandel6 &G = *gradient;
      G          = Mandel6{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int r = 0; r < 6; ++r)
          G[r] += g1[i] * s1.P[i][r] + g2[i] * s2.P[i][r];
      if (!hessian)
        return f;

      // Daleckii-Krein: h'' on the eigenprojections, the divided differences
      // of h' on the pairs; h'' at the pair's mean where the two eigenvalues
      // (nearly) coincide, the quotient's limit.
      const double width =
        1e-6 * (std::abs(s1.lambda[0]) + std::abs(s1.lambda[2]) +
                std::abs(s2.lambda[0]) + std::abs(s2.lambda[2]) + 1e-300);
      const unsigned int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
      Mandel6x6         &H           = *hessian;
      H                              = Mandel6x6{};
      for (unsigned int i = 0; i < 3; ++i)
        {
          add_outer(H, h1[i], s1.P[i]);
          add_outer(H, h2[i], s2.P[i]);
          for (unsigned int j = 0; j < 3; ++j)
            add_outer(H, -f2[i][j], s1.P[i], s2.P[j]);
        }
      for (unsigned int p = 0; p < 3; ++p)
        {
          const unsigned int i = pairs[p][0], k = pairs[p][1];
          double             t1 = 0, t2 = 0;
          const double       d1 = s1.lambda[i] - s1.lambda[k];
          const double       d2 = s2.lambda[i] - s2.lambda[k];
          if (std::abs(d1) > width)
            t1 = (g1[i] - g1[k]) / d1;
          else
            for (unsigned int j = 0; j < 3; ++j)
              t1 += a * (a - 1) *
                    power(std::abs(0.5 * (s1.lambda[i] + s1.lambda[k]) -
                                   s2.lambda[j]),
                          a - 2);
          if (std::abs(d2) > width)
            t2 = (g2[i] - g2[k]) / d2;
          else
            for (unsigned int j = 0; j < 3; ++j)
              t2 += a * (a - 1) *
                    power(std::abs(s1.lambda[j] -
                                   0.5 * (s2.lambda[i] + s2.lambda[k])),
                          a - 2);
          add_outer(H, 2 * t1, s1.S[p]);
          add_outer(H, 2 * t2, s2.S[p]);
        }
      return f;
    }

    double Yld2004::equivalent(const SymmetricTensor<2, 3> &sigma) const
    {
      const SymmetricTensor<2, 3> s = deviator(sigma);
      const double                n = s.norm();
      if (n == 0)
        return 0;
      return scale * n * std::pow(phi(s / n, nullptr, nullptr) / 4, 1 / a);
    }

    Yld2004::HalfSquare
    Yld2004::half_square(const SymmetricTensor<2, 3> &sigma) const
    {
      const auto m = half_square(to_mandel(sigma));
      return {m.value, from_mandel(m.gradient), from_mandel(m.hessian)};
    }

    Yld2004::HalfSquareMandel Yld2004::half_square(const Mandel6 &sigma) const
    {
      HalfSquareMandel out;
      Mandel6          s    = sigma;
      const double     mean = (s[0] + s[1] + s[2]) / 3;
      for (unsigned int r = 0; r < 3; ++r)
        s[r] -= mean;
      double n2 = 0;
      for (const double x : s)
        n2 += x * x;
      const double n = std::sqrt(n2);
      if (n == 0)
        {
          // No direction: von Mises's curvature, the start of any solve.
          out.value    = 0;
          out.gradient = Mandel6{};
          out.hessian  = to_mandel(1.5 * deviator_tensor<3>());
          return out;
        }
      // On the unit deviator u = s/n: sigma_bar(u) = k (phi/4)^(1/a),
      // grad sigma_bar = c1 grad phi, grad^2 sigma_bar = c1 grad^2 phi + c2
      // grad phi (x) grad phi, and grad^2 g = sigma_bar grad^2 sigma_bar +
      // grad sigma_bar (x) grad sigma_bar (degree 0): all as 6x6 matrices.
      Mandel6     &G  = out.gradient;
      Mandel6x6   &H  = out.hessian;
      const double f  = phi(from_mandel(s) / n, &G, &H);
      const double sb = scale * std::pow(f / 4, 1 / a);
      const double c1 = sb / (a * f), c2 = sb * (1 - a) / (a * a * f * f);
      const double cg = sb * c2 + c1 * c1;
      for (unsigned int r = 0; r < 6; ++r)
        for (unsigned int t = r; t < 6; ++t)
          H[t][r] = H[r][t] = sb * c1 * H[r][t] + cg * G[r] * G[t];
      for (auto &x : G)
        x *= n * sb * c1;
      out.value = 0.5 * sb * sb * n * n;
      return out;
    }

    double Yld2004::stress_ratio(const double angle) const
    {
      return 1 / equivalent(uniaxial_stress(angle));
    }

    double Yld2004::r_value(const double angle) const
    {
      const SymmetricTensor<2, 3> D =
        half_square(uniaxial_stress(angle)).gradient;
      const Tensor<1, 3> width({-std::sin(angle), std::cos(angle), 0.});
      return width * (D * width) / D[2][2];
    }

    double Yld2004::biaxial_ratio() const
    {
      SymmetricTensor<2, 3> b;
      b[0][0] = b[1][1] = 1;
      return 1 / equivalent(b);
    }

    double Yld2004::biaxial_r() const
    {
      SymmetricTensor<2, 3> b;
      b[0][0] = b[1][1]             = 1;
      const SymmetricTensor<2, 3> D = half_square(b).gradient;
      return D[1][1] / D[0][0];
    }

    double Yld2004::plane_strain_ratio() const
    {
      // The TD stress ratio t of sigma = diag(1, t, 0) at which the TD
      // rate dg/dsigma_22 vanishes: increasing in t (convexity), negative
      // in uniaxial RD tension (t = 0), positive at t = 1 for any sheet
      // that thins in balanced-biaxial tension.
      const auto td_rate = [this](const double t) {
        SymmetricTensor<2, 3> s;
        s[0][0]      = 1;
        s[1][1]      = t;
        const auto h = half_square(s);
        return std::make_pair(h.gradient[1][1], h.hessian[1][1][1][1]);
      };
      std::uintmax_t iterations = 50;
      const double   t = boost::math::tools::newton_raphson_iterate(td_rate,
                                                                  0.5,
                                                                  0.,
                                                                  1.,
                                                                  40,
                                                                  iterations);
      SymmetricTensor<2, 3> s;
      s[0][0] = 1;
      s[1][1] = t;
      return 1 / equivalent(s);
    }

    double Yld2004::mean_r() const
    {
      return (r_value(0) + 2 * r_value(M_PI / 4) + r_value(M_PI / 2)) / 4;
    }

    std::string Yld2004::summary() const
    {
      std::ostringstream s;
      s << "yield_exponent = " << a;
      for (int angle = 0; angle <= 90; angle += 15)
        s << "\nr" << angle << " = " << r_value(angle * M_PI / 180);
      for (int angle = 15; angle <= 90; angle += 15)
        s << "\nstress_ratio_" << angle << " = "
          << stress_ratio(angle * M_PI / 180);
      s << "\nstress_ratio_biaxial = " << biaxial_ratio()
        << "\nr_biaxial = " << biaxial_r()
        << "\nstress_ratio_plane_strain = " << plane_strain_ratio();
      return s.str();
    }
  } // namespace material
} // namespace formsolve
