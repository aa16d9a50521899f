#include <formsolve/material/directional.h>
#include <formsolve/material/hill48.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    using namespace dealii;

    Hill48 Hill48::isotropic()
    {
      return Hill48();
    }

    Hill48 Hill48::from_r_values(const double          r0,
                                 const double          r45,
                                 const double          r90,
                                 const TransverseShear shear)
    {
      Hill48 h;
      h.H = r0 / (1 + r0);
      h.G = 1 / (1 + r0);
      h.F = r0 / (r90 * (1 + r0));
      h.N = (r0 + r90) * (1 + 2 * r45) / (2 * r90 * (1 + r0));
      h.L = h.M = shear == TransverseShear::equal_to_n ? h.N : 1.5;
      return h;
    }

    Hill48 Hill48::from_normal_r(const double r, const TransverseShear shear)
    {
      return from_r_values(r, r, r, shear);
    }

    Hill48 Hill48::from_yield_stresses(const double          s45,
                                       const double          s90,
                                       const double          sb,
                                       const TransverseShear shear)
    {
      Hill48       h;
      const double a = 1 / (s90 * s90), b = 1 / (sb * sb);
      h.F = (a + b - 1) / 2;
      h.G = (1 + b - a) / 2;
      h.H = (1 + a - b) / 2;
      h.N = 2 / (s45 * s45) - (h.F + h.G) / 2;
      h.L = h.M = shear == TransverseShear::equal_to_n ? h.N : 1.5;
      return h;
    }

    Hill48 Hill48::from_parameters(const parameters::Anisotropy &a)
    {
      using namespace parameters;
      if (a.criterion == YieldCriterion::von_mises)
        return isotropic();
      if (a.calibration == HillCalibration::r_values)
        return a.r_values.size() == 1
                 ? from_normal_r(a.r_values[0], a.transverse_shear)
                 : from_r_values(a.r_values[0],
                                 a.r_values[1],
                                 a.r_values[2],
                                 a.transverse_shear);
      const auto &v = a.yield_stress_ratios;
      return from_yield_stresses(v[0],
                                 v[1],
                                 v.size() > 2 ? v[2] : 1.,
                                 a.transverse_shear);
    }

    Mandel6x6 Hill48::root() const
    {
      // In the orthotropy frame 3/2 Q is block diagonal: the normal block
      // (Mandel factor 1), singular along (1, 1, 1), and the shear diagonal
      // 3/2 * 2 Q_ijij. The root of the normal block by its eigenvectors.
      const Mandel6x6       q = to_mandel(dual());
      SymmetricTensor<2, 3> A;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          A[i][j] = 1.5 * q[i][j];
      const auto eig = eigenvectors(A);
      Mandel6x6  S{};
      for (const auto &[lambda, v] : eig)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            S[i][j] += std::sqrt(std::max(lambda, 0.)) * v[i] * v[j];
      for (unsigned int r = 3; r < 6; ++r)
        S[r][r] = std::sqrt(1.5 * q[r][r]);
      return S;
    }

    std::string Hill48::summary() const
    {
      std::ostringstream s;
      s << "hill_F = " << F << "\nhill_G = " << G << "\nhill_H = " << H
        << "\nhill_L = " << L << "\nhill_M = " << M << "\nhill_N = " << N;
      for (const int angle : {0, 45, 90})
        s << "\nr" << angle << " = " << r_value(angle * M_PI / 180);
      for (const int angle : {45, 90})
        s << "\nstress_ratio_" << angle << " = "
          << stress_ratio(angle * M_PI / 180);
      return s.str();
    }

    double Hill48::mean_r() const
    {
      return (r_value(0) + 2 * r_value(M_PI / 4) + r_value(M_PI / 2)) / 4;
    }

    SymmetricTensor<4, 3> Hill48::primal() const
    {
      // sigma_bar^2 = F(s22 - s33)^2 + G(s33 - s11)^2 + H(s11 - s22)^2
      //             + 2 L s23^2 + 2 M s31^2 + 2 N s12^2.
      // deal.II's SymmetricTensor<4, 3> has the minor symmetries only: the
      // (ij, kl) and (kl, ij) entries are set apart.
      SymmetricTensor<4, 3> P;
      P[0][0][0][0] = G + H;
      P[1][1][1][1] = F + H;
      P[2][2][2][2] = F + G;
      P[0][0][1][1] = P[1][1][0][0] = -H;
      P[1][1][2][2] = P[2][2][1][1] = -F;
      P[0][0][2][2] = P[2][2][0][0] = -G;
      // s : P : s counts each shear entry four times: 4 P_1212 s12^2.
      P[1][2][1][2] = L / 2;
      P[0][2][0][2] = M / 2;
      P[0][1][0][1] = N / 2;
      return P;
    }

    SymmetricTensor<4, 3> Hill48::dual() const
    {
      // The normal block of P's pseudo-inverse on deviators (rows summing
      // to zero), and the shear entries (anisotropy.md sections 2, 3).
      const double          d = 9 * determinant();
      SymmetricTensor<4, 3> Q;
      Q[0][0][0][0] = (4 * F + G + H) / d;
      Q[1][1][1][1] = (F + 4 * G + H) / d;
      Q[2][2][2][2] = (F + G + 4 * H) / d;
      Q[0][0][1][1] = Q[1][1][0][0] = -(2 * F + 2 * G - H) / d;
      Q[0][0][2][2] = Q[2][2][0][0] = -(2 * F - G + 2 * H) / d;
      Q[1][1][2][2] = Q[2][2][1][1] = -(2 * G + 2 * H - F) / d;
      // D : Q : D counts each shear entry four times: 2 D12^2 / N.
      Q[1][2][1][2] = 1 / (2 * L);
      Q[0][2][0][2] = 1 / (2 * M);
      Q[0][1][0][1] = 1 / (2 * N);
      return Q;
    }

    double Hill48::r_value(const double angle) const
    {
      // The flow rule D ~ P : sigma; width (in-plane, normal to the load)
      // over thickness strain rate.
      const SymmetricTensor<2, 3> D = primal() * uniaxial_stress(angle);
      const Tensor<1, 3> width({-std::sin(angle), std::cos(angle), 0.});
      return width * (D * width) / D[2][2];
    }

    double Hill48::stress_ratio(const double angle) const
    {
      // sigma_bar(s u) = s sqrt(u : P : u) for a uniaxial unit stress u.
      const SymmetricTensor<4, 3> P = primal();
      return std::sqrt(uniaxial_stress(0) * (P * uniaxial_stress(0)) /
                       (uniaxial_stress(angle) * (P * uniaxial_stress(angle))));
    }

  } // namespace material
} // namespace formsolve
