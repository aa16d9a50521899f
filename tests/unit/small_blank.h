// The parameters of a small test blank: 20 mm across, 1 mm thick, round for
// the axisymmetric model, square otherwise, the default tools.
#pragma once

#include <formsolve/parameters/parameters.h>

namespace test
{
  inline formsolve::parameters::Run
  small_blank(const formsolve::model::Model      m,
              const formsolve::parameters::Mesh &mesh)
  {
    using namespace formsolve;
    parameters::Run prm;
    prm.geometry.model          = m;
    prm.geometry.blank_shape    = m == model::Model::axisymmetric
                                    ? parameters::BlankShape::round
                                    : parameters::BlankShape::rectangle;
    prm.geometry.blank_diameter = 20;
    prm.geometry.blank_length   = 20;
    prm.geometry.blank_width    = 20;
    prm.geometry.thickness      = 1;
    prm.mesh                    = mesh;
    return prm;
  }
} // namespace test
