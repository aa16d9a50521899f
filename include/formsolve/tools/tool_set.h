// The tools of a run, built from the Tools subsection, and their motion.
#pragma once

#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/tools.h>
#include <formsolve/tools/rigid_tool.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    template <int dim>
    class ToolSet
    {
    public:
      static constexpr unsigned int none = static_cast<unsigned int>(-1);

      /// Builds the enabled tools around a sheet occupying 0 <= z <= thickness.
      ToolSet(const parameters::Tools   &p,
              const parameters::Contact &c,
              const double               thickness);

      unsigned int          size() const { return tools.size(); }
      const RigidTool<dim> &operator[](const unsigned int i) const
      {
        return *tools[i];
      }
      double friction_coefficient(const unsigned int i) const
      {
        return friction[i];
      }
      /// Fixed penalty of tool i (N/mm^3).
      double penalty_factor(const unsigned int i) const { return penalty[i]; }
      /// Allowed penetration delta into tool i (mm).
      double allowed_penetration(const unsigned int i) const
      {
        return allowed[i];
      }
      /// Column/field name of tool i: punch, die, blank_holder.
      const std::string &key(const unsigned int i) const { return keys[i]; }
      unsigned int       punch_index() const { return 0; }
      /// Index of the die / blank holder, or none.
      unsigned int die_index() const { return die; }
      unsigned int holder_index() const { return holder; }

      /// Velocity of tool @p i along z (mm/s), e.g. the blank holder under
      /// force control.
      void   set_axial_velocity(const unsigned int i, const double w);
      double axial_velocity(const unsigned int i) const;

      void advance(const double dt);
      /// What reading the tools' files changed (orientation), to be said.
      const std::vector<std::string> &notes() const
      {
        return orientation_notes;
      }
      /// Put tool @p i back where a checkpoint found it.
      void   restore(const unsigned int    i,
                     const Tensor<1, dim> &displacement,
                     const double          travel,
                     const Tensor<1, dim> &velocity);
      double punch_travel() const { return tools[0]->travel(); }
      double punch_stroke() const { return stroke; }
      double punch_speed() const { return speed; }

    private:
      std::vector<std::unique_ptr<RigidTool<dim>>> tools;
      std::vector<double>                          friction, penalty, allowed;
      std::vector<std::string>                     keys, orientation_notes;
      double                                       stroke, speed;
      unsigned int                                 die = none, holder = none;
    };
  } // namespace tools
} // namespace formsolve
