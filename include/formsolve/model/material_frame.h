// The orthotropy frame of the sheet at a point, RD, TD, ND in the 3x3 frame of
// the kinematics: the initial frame (RD at the rolling-direction angle to x in
// the sheet plane, ND the sheet normal) turned by the rotation R of the polar
// decomposition F = R U of the deformation from the initial configuration, so
// that the frame bends with the sheet into the cup wall (doc/theory.md,
// section 3a).
#pragma once

#include <deal.II/base/tensor.h>

namespace formsolve
{
  namespace model
  {
    using dealii::Tensor;

    /// R of F = R U (det F > 0), by Higham's scaled Newton iteration
    /// X <- (z X + X^-T / z)/2, z = |det X|^(-1/dim).
    template <int dim>
    Tensor<2, dim> polar_rotation(const Tensor<2, dim> &F);

    template <int dim>
    class MaterialFrame
    {
    public:
      /// @p rolling_direction: angle of RD from the x axis towards y
      /// (radians). In a 2-D section ((x, z, y) in plane strain, (r, z,
      /// theta) in axisymmetry, where only normal anisotropy is allowed and
      /// the angle is 0) ND is the axial direction of the flat blank.
      explicit MaterialFrame(const double rolling_direction);

      /// Columns RD, TD, ND now, for the deformation gradient @p F from the
      /// initial configuration.
      Tensor<2, 3> operator()(const Tensor<2, dim> &F) const;

      /// The same at the start (F = I).
      const Tensor<2, 3> &initial() const { return start; }

    private:
      Tensor<2, 3> start;
    };
  } // namespace model
} // namespace formsolve
