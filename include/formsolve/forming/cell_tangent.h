// The cell tangent of the body (doc/theory.md eq. 4, 4b and 5) as three small
// dense products instead of one B_i : C : B_j contraction per DoF pair and
// point. Every term is a sum over points of products of per-point rows:
// 2 mu B_i : B_j and the deviatoric trace term come from one matrix
// P = sum_q mu_q psi_q (x) psi_q of the scalar shape gradients (and phi/r
// in axisymmetry), the rate terms from S^T U, the volumetric penalty from
// T^T T at the reduced points (doc/theory.md section 5a). A material without
// that isotropic form gives its 6x6 tangent instead, and the deviatoric part
// is the product G^T (C G) of the Mandel rows of B.
#pragma once

#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>

#include <formsolve/material/mandel.h>
#include <formsolve/model/kinematics.h>

#include <vector>

namespace formsolve
{
  namespace solver
  {
    template <int dim>
    class CellTangent
    {
    public:
      /// @p fe: the vector element (dim copies of one scalar element);
      /// @p hoop: axisymmetric kinematics (the phi/r term).
      CellTangent(const dealii::FiniteElement<dim> &fe,
                  const unsigned int                n_points,
                  const unsigned int                n_reduced_points,
                  const bool                        hoop);

      /// Deviatoric part at point @p q of the full rule:
      /// 2 mu (B_i : B_j - tr_i tr_j / 3) + s_i u_j + u_i s_j, with mu, s and
      /// u already weighted by the volume element (the assembler's
      /// s = B : D', u = beta_h/2 s + beta_p t).
      void add_deviatoric(const unsigned int                     q,
                          const std::vector<model::ShapeStrain> &B,
                          const double                           mu,
                          const std::vector<double>             &s,
                          const std::vector<double>             &u);

      /// Deviatoric part at point @p q of the full rule for any material:
      /// B_i : C : B_j with @p C the material tangent already weighted by
      /// the volume element (as 6x6 products in Mandel's notation).
      void add_general(const unsigned int                     q,
                       const std::vector<model::ShapeStrain> &B,
                       const dealii::SymmetricTensor<4, 3>   &C);
      /// The same with the tangent in Mandel's notation, times @p weight.
      void add_general(const unsigned int                     q,
                       const std::vector<model::ShapeStrain> &B,
                       const material::Mandel6x6             &C,
                       const double                           weight);

      /// Volumetric penalty at point @p q of the reduced rule:
      /// weight tr_i tr_j.
      void add_volumetric(const unsigned int         q,
                          const std::vector<double> &tr,
                          const double               weight);

      /// The symmetric cell matrix of the points added since the last call;
      /// resets the rows.
      void finish(dealii::FullMatrix<double> &K);

    private:
      unsigned int n_psi; // per scalar function: dim gradients (+ phi/r)
      bool         hoop;
      std::vector<unsigned int>  component, node; // of each DoF
      dealii::FullMatrix<double> psi, psi_w;      // points x scalar columns
      dealii::FullMatrix<double> S, U;            // points x DoFs
      dealii::FullMatrix<double> T, T_w;          // reduced points x DoFs
      dealii::FullMatrix<double> P, E, V;         // the three products
      // The general form: Mandel rows of B and of C B, 6 per point.
      dealii::FullMatrix<double> G, CG;
      bool                       product_form = false, general_form = false;

      unsigned int column(const unsigned int a, const unsigned int k) const
      {
        return a * n_psi + k;
      }
    };
  } // namespace solver
} // namespace formsolve
