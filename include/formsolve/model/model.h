// Which part of the scene is modelled: the axisymmetric r-z section, or a
// half, quarter or full 3-D sheet. main dispatches on it (2-D or 3-D code).
#pragma once

#include <string>

namespace formsolve
{
  namespace model
  {
    enum class Model
    {
      axisymmetric, // 2-D section (r, z), the z axis is the axis of revolution
      half,         // 3-D, x >= 0, symmetry plane x = 0
      quarter,      // 3-D, x >= 0 and y >= 0, symmetry planes x = 0, y = 0
      full          // 3-D, no symmetry
    };

    /// "axisymmetric|half|quarter|full", for Patterns::Selection.
    std::string model_names();
    /// Throws naming Geometry/Model for an unknown name.
    Model       parse_model(const std::string &name);
    std::string name(const Model m);

    /// Space dimension of the discretisation: 2 for axisymmetric, else 3.
    unsigned int space_dimension(const Model m);
    /// Factor from the modelled part to the full part. Axisymmetric models
    /// integrate over the full ring (2 pi r), so their factor is 1.
    double symmetry_factor(const Model m);
    /// Whether the plane x = 0 (y = 0) bounds the model with a symmetry
    /// condition (no normal velocity).
    bool symmetric_in_x(const Model m);
    bool symmetric_in_y(const Model m);
  } // namespace model
} // namespace formsolve
