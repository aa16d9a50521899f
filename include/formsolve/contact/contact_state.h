// The contact state that lives across iterations, solves and steps: one
// record per (sheet surface node, tool). Penalty strategies write the factor,
// the strict scale and the multiplier; track_status() writes the status and
// the chatter guard. The contact search reads the multiplier through
// shift(). The State owns it, so step control restores it with the rest of
// a rejected step, and refinement carries it over (State::
// transferable_fields).
#pragma once

#include <formsolve/contact/contact_set.h>

#include <vector>

namespace formsolve
{
  namespace contact
  {
    struct ContactRecord
    {
      double factor = 0; // last estimated penalty factor (N/mm), 0: none yet
      double scale  = 1; // adaptive-strict: persistent factor scaling (-)
      double shift  = 0; // augmented Lagrangian: lambda/eps as a gap (mm)
      bool   active = false;       // status at the last evaluated iterate
      unsigned int flips  = 0;     // status changes in the current solve
      bool         locked = false; // chatter guard: status frozen this solve
    };

    class ContactState
    {
    public:
      /// Fresh records for @p n_nodes surface nodes and @p n_tools tools.
      void reset(const unsigned int n_nodes, const unsigned int n_tools)
      {
        tools = n_tools;
        records.assign(n_nodes * n_tools, ContactRecord());
        baseline = true;
      }

      /// A Newton solve begins: no flips, nothing locked; the next
      /// track_status() only records the status.
      void begin_solve();

      /// After each contact search: records the status of every pair of
      /// @p set and counts its changes within the solve. A pair that has
      /// changed @p max_flips times is locked for the rest of the solve
      /// (ContactPair::locked: its changes no longer count as changes of the
      /// contact set in the convergence test; its force and stiffness still
      /// follow the law, so an open locked pair adds nothing). Pair indices
      /// change between steps, records do not.
      template <int dim>
      void track_status(ContactSet<dim> &set, const unsigned int max_flips);

      ContactRecord &operator()(const unsigned int node,
                                const unsigned int tool)
      {
        return records[node * tools + tool];
      }
      const ContactRecord &operator()(const unsigned int node,
                                      const unsigned int tool) const
      {
        return records[node * tools + tool];
      }

      double shift(const unsigned int node, const unsigned int tool) const
      {
        return records.empty() ? 0. : (*this)(node, tool).shift;
      }

      unsigned int size() const { return records.size(); }

    private:
      unsigned int               tools    = 0;
      bool                       baseline = true;
      std::vector<ContactRecord> records;
    };
  } // namespace contact
} // namespace formsolve
