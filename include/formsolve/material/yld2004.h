// Barlat's Yld2004-18p (Barlat et al., Int. J. Plasticity 21 (2005) 1009)
// and Hosford's isotropic criterion as its unit-coefficient case, in the
// orthotropy frame (1 = RD, 2 = TD, 3 = ND; doc/theory.md, section 3b, eq. 3d):
//   sigma_bar^a = 1/4 sum_i sum_j |S'_i - S''_j|^a,
// S', S'' the principal values of L' : sigma and L'' : sigma, L = C P_dev,
// C = [[0, -c12, -c13], [-c21, 0, -c23], [-c31, -c32, 0]] + diag(c44, c55,
// c66) on (11, 22, 33, 23, 31, 12). Normalised so that sigma_bar is the
// rolling direction's uniaxial flow stress.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <formsolve/material/mandel.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    struct Anisotropy;
  }

  namespace material
  {
    using dealii::SymmetricTensor;

    class Yld2004
    {
    public:
      /// @p c1, @p c2: c12, c13, c21, c23, c31, c32, c44, c55, c66 of C', C''.
      Yld2004(const std::vector<double> &c1,
              const std::vector<double> &c2,
              const double               exponent);
      /// Hosford's |s1 - s2|^a + |s2 - s3|^a + |s3 - s1|^a = 2 sigma_bar^a.
      static Yld2004 hosford(const double exponent);
      /// From the Material entries; a set without a positive RD yield
      /// stress or not strictly convex is refused, naming the entries.
      static Yld2004 from_parameters(const parameters::Anisotropy &a);

      /// A unit deviatoric direction (of 500 spread over the sphere) where
      /// the Hessian of g is not positive definite on deviators, or zero.
      SymmetricTensor<2, 3> least_convex() const;

      /// sigma_bar of @p sigma (the hydrostatic part does not count).
      double equivalent(const SymmetricTensor<2, 3> &sigma) const;

      /// g = sigma_bar^2 / 2, its gradient and its Hessian with respect to
      /// the stress. g is homogeneous of degree 2: the gradient of degree 1,
      /// the Hessian of degree 0, with the identity in its null space.
      struct HalfSquare
      {
        double                value;
        SymmetricTensor<2, 3> gradient;
        SymmetricTensor<4, 3> hessian;
      };
      HalfSquare half_square(const SymmetricTensor<2, 3> &sigma) const;
      /// The same in Mandel's notation (the local solve's own).
      struct HalfSquareMandel
      {
        double    value;
        Mandel6   gradient;
        Mandel6x6 hessian;
      };
      HalfSquareMandel half_square(const Mandel6 &sigma) const;

      /// Uniaxial flow stress at @p angle (radians) to RD over RD's.
      double stress_ratio(const double angle) const;
      /// r-value of uniaxial tension at @p angle: width over thickness
      /// strain rate by the flow rule D ~ grad sigma_bar.
      double r_value(const double angle) const;
      /// Balanced-biaxial flow stress over RD's.
      double biaxial_ratio() const;
      /// TD over RD strain rate in balanced-biaxial tension.
      double biaxial_r() const;
      /// RD stress of plane-strain tension along RD (no TD strain rate,
      /// no normal stress) over the RD uniaxial flow stress.
      double plane_strain_ratio() const;
      /// (r0 + 2 r45 + r90)/4.
      double mean_r() const;

      /// "key = value" lines: the exponent, sigma/sigma_0 and r every 15
      /// degrees, the biaxial and plane-strain points (run summary).
      std::string summary() const;
      /// Where the coefficients were fitted: "key = value" lines of the
      /// fitted coefficients, each datum beside the fit and the RMS errors
      /// (run summary), and one line of it (the run's header); else empty.
      const std::string &fit_lines() const { return fit_report; }
      const std::string &fit_headline() const { return headline; }

      double exponent() const { return a; }

    private:
      /// phi = sum_ij |S'_i - S''_j|^a of a stress scaled to order one, with
      /// its derivatives if @p derivatives.
      double phi(const SymmetricTensor<2, 3> &sigma,
                 Mandel6                     *gradient,
                 Mandel6x6                   *hessian) const;

      SymmetricTensor<4, 3> L1, L2; // C' P_dev, C'' P_dev
      Mandel6x6             M1, M2; // the same as 6x6 matrices
      double                a;
      double                scale = 1; // 1/sigma_bar of unit RD tension
      std::string           fit_report, headline; // fitted coefficients
    };
  } // namespace material
} // namespace formsolve
