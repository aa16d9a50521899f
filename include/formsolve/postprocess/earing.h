// The cup-height profile of a drawn round blank (earing): the height of the
// rim's top edge above the cup bottom's outer surface against the angle to
// the rolling direction, from the sheet's columns (3-D models).
#pragma once

#include <formsolve/model/model.h>
#include <formsolve/postprocess/sheet_measures.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    struct EaringProfile
    {
      std::vector<double> angle;  // degrees from RD, over the model's range
      std::vector<double> height; // mm
      double              mean = 0, amplitude = 0; // mm; amplitude = max - min
      unsigned int        ears = 0; // prominent maxima, full circle; 0 if flat
      std::vector<double> ear_angles; // degrees from RD, full circle
    };

    /// The profile every @p step degrees from the rim columns of @p cols
    /// (rank 0), the angles counted from @p rolling_direction (degrees from
    /// x); the symmetry planes of @p model extend it to the full circle for
    /// the ears. Empty without rim columns.
    EaringProfile earing_profile(const std::vector<SheetColumn<3>> &cols,
                                 const model::Model                 model,
                                 const double rolling_direction,
                                 const double step = 2.5);

    /// earing.csv (angle_deg,cup_height_mm) in @p directory.
    void write_earing(const EaringProfile &p, const std::string &directory);
  } // namespace postprocess
} // namespace formsolve
