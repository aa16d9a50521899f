// The tools of a run, built from the Tools subsection, and their motion:
// the punch and prescribed tools at a speed along a direction, the fixed
// ones still, the force-controlled ones (the blank holder under Control =
// force, additional tools with Motion = force) at the velocity their force
// equation gives (solver/force_equations.h).
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
    /// How tool i moves.
    template <int dim>
    struct Motion
    {
      parameters::ToolMotion kind = parameters::ToolMotion::fixed;
      /// Unit direction of the motion (prescribed) or of the force on the
      /// sheet (force).
      Tensor<1, dim>         direction;
      double                 speed  = 0; // mm/s (prescribed)
      double                 stroke = 0; // mm; 0: no end (prescribed)
      parameters::ForceCurve force;      // N on the full part (force)
    };

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
      /// Column/field name of tool i: punch, die, blank_holder, or an
      /// additional tool's name in lower case with '_' for spaces.
      const std::string &key(const unsigned int i) const { return keys[i]; }
      unsigned int       punch_index() const { return 0; }
      /// Index of the die / blank holder, or none.
      unsigned int die_index() const { return die; }
      unsigned int holder_index() const { return holder; }
      /// Tools first_additional() .. size()-1 are Tools/Additional tools.
      unsigned int first_additional() const { return additional; }

      const Motion<dim> &motion(const unsigned int i) const
      {
        return motions[i];
      }
      /// The tools under force control, in tool order.
      std::vector<unsigned int> force_controlled() const;
      /// Extra refinement levels near tool i's radii set by its own entry
      /// (additional tools; 0 for punch, die and holder).
      unsigned int refinement_level(const unsigned int i) const
      {
        return levels[i];
      }

      /// Velocity of tool @p i along its Motion direction (mm/s), a tool
      /// under force control.
      void   set_speed_along(const unsigned int i, const double u);
      double speed_along(const unsigned int i) const;
      /// The velocity tool @p i would have at speed @p u along its Motion
      /// direction (mm/s); the tool is not changed.
      Tensor<1, dim> velocity_along(const unsigned int i, const double u) const
      {
        return u * motions[i].direction;
      }
      /// Every tool's velocity now (mm/s).
      std::vector<Tensor<1, dim>> velocities() const;

      /// A step of @p dt begins: a prescribed tool with a Stroke moves so
      /// that it lands on it exactly and then stands.
      void begin_step(const double dt);
      void advance(const double dt);
      /// What reading the tools' files changed (orientation), to be said.
      const std::vector<std::string> &notes() const
      {
        return orientation_notes;
      }
      /// +1: tool @p i is above the sheet (comes down to it), -1: below.
      int side(const unsigned int i) const { return sides[i]; }
      /// The distance tool @p i keeps from the part at the start (mm) when
      /// its Gap is measured from the part; NaN when from the blank.
      double gap_to_part(const unsigned int i) const { return to_part[i]; }
      /// Put tool @p i back where a checkpoint found it.
      void   restore(const unsigned int    i,
                     const Tensor<1, dim> &displacement,
                     const double          travel,
                     const Tensor<1, dim> &velocity);
      double punch_travel() const { return tools[0]->travel(); }
      double punch_stroke() const { return stroke; }
      double punch_speed() const { return speed; }

    private:
      /// Tool @p t if enabled: its solid on side @p sa of its outline
      /// (-1 inside), on side @p sb of the sheet (+1 above).
      void add(const parameters::Tool    &t,
               const int                  sa,
               const int                  sb,
               const Motion<dim>         &m,
               const unsigned int         level,
               const parameters::Contact &c,
               const double               thickness);

      std::vector<std::unique_ptr<RigidTool<dim>>> tools;
      std::vector<double>                          friction, penalty, allowed;
      std::vector<int>                             sides;
      std::vector<double>                          to_part;
      std::vector<std::string>                     keys, orientation_notes;
      std::vector<Motion<dim>>                     motions;
      std::vector<unsigned int>                    levels;
      double                                       stroke, speed;
      unsigned int die = none, holder = none, additional = 0;
    };
  } // namespace tools
} // namespace formsolve
