// The contact state that lives across iterations and steps, one record per
// (sheet surface node, tool). Only penalty strategies write it; the contact
// search reads the multiplier through shift(). The State owns it, so step
// control restores it with the rest of a rejected step.
#pragma once

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
    };

    class ContactState
    {
    public:
      /// Fresh records for @p n_nodes surface nodes and @p n_tools tools.
      void reset(const unsigned int n_nodes, const unsigned int n_tools)
      {
        tools = n_tools;
        records.assign(n_nodes * n_tools, ContactRecord());
      }

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
      unsigned int               tools = 0;
      std::vector<ContactRecord> records;
    };
  } // namespace contact
} // namespace formsolve
