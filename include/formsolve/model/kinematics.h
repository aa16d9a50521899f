// The one owner of the kinematics: the 3x3 rate of deformation (with the hoop
// rate v_r/r in axisymmetry, no strain along y in plane strain), the strain of
// a shape function (its linearisation) and the volume element (2 pi r JxW in
// axisymmetry, b JxW for the width b of a plane-strain section). Material
// laws only ever see 3x3 tensors; assembly, history, integrals, contact areas
// and output all go through this class (doc/theory.md, section 1).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_update_flags.h>

namespace formsolve
{
  namespace model
  {
    using dealii::Point;
    using dealii::SymmetricTensor;
    using dealii::Tensor;

    /// Strain rate of one vector shape function phi e_c in the 3x3 frame of
    /// the kinematics ((x, y, z) in 3-D, (r, z, theta) in axisymmetry):
    /// B = sym(e_c (x) g) + hoop e_theta (x) e_theta.
    struct ShapeStrain
    {
      unsigned int component = 0;
      Tensor<1, 3> gradient; // of the scalar shape function, 3-D frame
      double       hoop = 0; // phi/r for a radial shape function, else 0

      double trace() const { return gradient[component] + hoop; }

      /// B itself.
      SymmetricTensor<2, 3> tensor() const
      {
        SymmetricTensor<2, 3> t;
        for (unsigned int k = 0; k < 3; ++k)
          t[component][k] += (k == component ? 1. : 0.5) * gradient[k];
        t[2][2] += hoop;
        return t;
      }

      /// S : B for a symmetric S.
      double contract(const SymmetricTensor<2, 3> &S) const
      {
        double s = S[2][2] * hoop;
        for (unsigned int k = 0; k < 3; ++k)
          s += S[component][k] * gradient[k];
        return s;
      }
    };

    /// B_a : B_b.
    inline double contract(const ShapeStrain &a, const ShapeStrain &b)
    {
      return 0.5 *
               ((a.component == b.component ? a.gradient * b.gradient : 0.) +
                a.gradient[b.component] * b.gradient[a.component]) +
             a.hoop * b.hoop;
    }

    template <int dim>
    class Kinematics
    {
    public:
      /// dim = 2: axisymmetric (r = x_0, z = x_1) or, if false, plane strain
      /// (x = x_0, z = x_1, the 3x3 frame's third axis is y) over the width
      /// @p depth along y (mm). dim = 3: Cartesian; @p axisymmetric must be
      /// false and @p depth 1.
      explicit Kinematics(const bool axisymmetric, const double depth = 1.);

      bool axisymmetric() const { return axi; }

      /// The width a plane-strain section stands for (1 in 3-D).
      double depth() const { return width; }

      /// What FEValues must compute besides gradients and JxW.
      dealii::UpdateFlags update_flags() const;

      /// 2 pi r in axisymmetry (the full ring), the width in plane strain,
      /// else 1: dV = factor JxW.
      double volume_factor(const Point<dim> &x) const;

      /// D = sym grad v in 3x3, with D_thth = v_r / r in axisymmetry.
      SymmetricTensor<2, 3> rate_of_deformation(const Tensor<2, dim> &grad_v,
                                                const Tensor<1, dim> &v,
                                                const Point<dim>     &x) const;

      /// Strain of the shape function phi e_c with gradient @p grad and
      /// value @p phi at @p x.
      ShapeStrain shape_strain(const unsigned int    c,
                               const Tensor<1, dim> &grad,
                               const double          phi,
                               const Point<dim>     &x) const;

      /// A vector of the model's space in the 3x3 frame (zero hoop part).
      static Tensor<1, 3> embed(const Tensor<1, dim> &a);

    private:
      bool   axi;
      double width;
    };
  } // namespace model
} // namespace formsolve
