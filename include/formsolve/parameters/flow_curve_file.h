// Material/Flow curve file: a tabulated flow curve as material cards
// deliver it, read and checked (doc/theory.md, eq. 2).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    /// The (equivalent plastic strain, flow stress MPa) points of the CSV
    /// @p file, one per line (a header line and '#' lines skipped); at least
    /// two, strains from 0 up and increasing, stresses positive and not
    /// falling. Throws naming Material/Flow curve file and the line.
    std::vector<std::pair<double, double>>
    read_flow_curve(const std::string &file);
  } // namespace parameters
} // namespace formsolve
