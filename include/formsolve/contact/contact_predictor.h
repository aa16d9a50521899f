// The step's predictor at the contact nodes. The previous step's velocity,
// read in the updated configuration, lifts nodes that slid over a curved
// tool (or moved with the holder) off it by a few micrometres: their pairs
// are then open at the first linearisation, and the first Newton direction,
// which knows nothing of those tools, moves the sheet freely into them (the
// line search then took alpha ~ 0.04 in most steps, doc/convergence.md).
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/contact/contact_state.h>
#include <formsolve/tools/tool_set.h>

namespace formsolve
{
  namespace contact
  {
    /// Adds to @p change (owned entries, to be compressed with 'add') the
    /// normal velocity that makes every pair of @p set which was in contact
    /// at the last iterate of the previous solve (@p state's status) and is
    /// open at this predictor just touch its tool at the end of the step:
    /// predicted gap = shift - touch_depth * the tool's allowed penetration,
    /// a force of practically zero (doc/theory.md eq. 10b). Pairs that stay
    /// closed, and pairs not in contact before, are left alone. Returns the
    /// number of pairs moved on this rank.
    template <int dim>
    unsigned int keep_contact(const ContactSet<dim>                 &set,
                              const ContactState                    &state,
                              const tools::ToolSet<dim>             &tools,
                              const double                           dt,
                              dealii::TrilinosWrappers::MPI::Vector &change);

    /// Depth below the shift at which keep_contact() places a pair, in units
    /// of the allowed penetration: exactly at the shift the rounding of the
    /// next search (which differs with the number of ranks) would decide
    /// whether the pair is active.
    inline constexpr double touch_depth = 1e-6;
  } // namespace contact
} // namespace formsolve
