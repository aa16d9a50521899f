// Which part of the scene is modelled: a 2-D section (the axisymmetric r-z
// section, or the plane-strain x-z section of a long part), or a half,
// quarter or full 3-D sheet. main dispatches on it (2-D or 3-D code).
#pragma once

#include <string>
#include <vector>

namespace formsolve
{
  namespace model
  {
    enum class Model
    {
      axisymmetric, // 2-D section (r, z), the z axis is the axis of revolution
      plane_strain, // 2-D section (x, z), x >= 0, symmetry plane x = 0; no
                    // strain along y, the part's width along y
      half,         // 3-D, x >= 0, symmetry plane x = 0
      quarter,      // 3-D, x >= 0 and y >= 0, symmetry planes x = 0, y = 0
      full,         // 3-D, no symmetry
      slice         // 3-D, x >= 0, 0 <= y <= width, symmetry planes x = 0
                    // and both y faces: the plane-strain section in 3-D
    };

    /// "axisymmetric|plane strain|half|quarter|full|slice", for
    /// Patterns::Selection.
    std::string model_names();
    /// Throws naming Geometry/Model for an unknown name.
    Model       parse_model(const std::string &name);
    std::string name(const Model m);

    /// Names of the coordinates of a point: r, z (axisymmetric); x, z
    /// (plane strain); x, y, z.
    std::vector<std::string> coordinate_names(const Model m);

    /// Space dimension of the discretisation: 2 for the sections, else 3.
    unsigned int space_dimension(const Model m);
    /// Factor from the modelled part to the full part. Axisymmetric models
    /// integrate over the full ring (2 pi r), so their factor is 1; the
    /// plane-strain section and the slice are the half x >= 0 of the part's
    /// width.
    double symmetry_factor(const Model m);
    /// Whether the plane x = 0 (y = 0, and for the slice also y = width)
    /// bounds the model with a symmetry condition (no normal velocity).
    bool symmetric_in_x(const Model m);
    bool symmetric_in_y(const Model m);
  } // namespace model
} // namespace formsolve
