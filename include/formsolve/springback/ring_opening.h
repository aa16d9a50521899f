// The split-ring test's measure (Demeri): the opening of a ring slit along
// its generator at +y (Springback/Slit), twice the slit face's springback
// displacement along x, which the symmetry across x = 0 mirrors.
#pragma once

#include <formsolve/springback/release.h>

namespace formsolve
{
  namespace springback
  {
    struct RingOpening
    {
      unsigned int nodes = 0;         // of the slit face
      double       mean  = 0;         // mm, > 0: the ring opens
      double       low = 0, high = 0; // over the face's nodes
    };

    /// On the released part's nodes at x = 0, y > 0 (nodes placed by
    /// @p configuration, the release's). Collective.
    template <int dim>
    RingOpening ring_opening(const Release<dim>         &release,
                             const dealii::Mapping<dim> &configuration);
  } // namespace springback
} // namespace formsolve
