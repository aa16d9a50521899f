// A draw bead's line as the points its line force is integrated at: Gauss
// points on pieces of each segment in plan view (3-D), or the one point of
// a 2-D section with the ring (axisymmetric) or the width (plane strain)
// as its length. Built once from Tools/Draw beads/<name>.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <formsolve/model/kinematics.h>
#include <formsolve/model/model.h>
#include <formsolve/parameters/draw_beads.h>

#include <vector>

namespace formsolve
{
  namespace beads
  {
    template <int dim>
    struct BeadPoint
    {
      dealii::Point<dim>     plan;   // x, y (3-D; z unused) or x (2-D)
      double                 weight; // mm of line the point stands for
      dealii::Tensor<1, dim> normal; // unit, in plan view, across the line
      double                 along;  // 0 at the line's start, 1 at its end
    };

    /// The points of @p bead, pieces at most @p piece long (3-D), on the
    /// part of the line inside the model @p m (symmetry planes cut it; a
    /// slice is @p slice_width wide).
    template <int dim>
    std::vector<BeadPoint<dim>> bead_points(const parameters::DrawBead   &bead,
                                            const model::Kinematics<dim> &k,
                                            const double                  piece,
                                            const model::Model            m,
                                            const double slice_width);
  } // namespace beads
} // namespace formsolve
