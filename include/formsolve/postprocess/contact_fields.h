// Nodal contact fields for the VTU files: predicted gap, contact pressure and
// penalty factor at each sheet surface node.
#pragma once

#include <formsolve/postprocess/vtu_writer.h>
#include <formsolve/state/state.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    template <int dim>
    class ContactFields
    {
    public:
      /// Fills the fields from the state's contact set with factors
      /// @p epsilon (one per pair); the gap is capped at @p search_distance.
      void fill(const state::State<dim>   &state,
                const std::vector<double> &epsilon,
                const double               search_distance);

      /// The three fields as named nodal scalars (valid until the next fill).
      std::vector<NodalScalar> scalars() const;

    private:
      std::array<VectorType, 3> ghosted; // gap, pressure, penalty factor
    };
  } // namespace postprocess
} // namespace formsolve
