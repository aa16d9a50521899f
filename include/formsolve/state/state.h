// What a step changes, in one object: mesh, DoFs, velocity, displacement,
// quadrature history, tool positions, contact nodes and contact state, the
// tools' force control and the time. Refinement transfers it as one; step
// control saves and restores the part a failed step may have touched.
#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/contact/contact_state.h>
#include <formsolve/model/current_mapping.h>
#include <formsolve/model/kinematics.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/state/history_update.h>
#include <formsolve/state/quadrature_history.h>
#include <formsolve/tools/tool_set.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace state
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// A tool under force control (tools::ToolSet::force_controlled()):
    /// its velocity along its direction is one more unknown of each step.
    struct ForceControl
    {
      unsigned int tool     = 0;
      double       target   = 0;    // set force on the modelled part (N)
      double       velocity = 0;    // along the direction, last step (mm/s)
      bool         active   = true; // false once the holder is released
    };

    /// The blank holder lets go of the blank when its flange has left it.
    /// A draw bead in the last converged step (modelled part), and what it
    /// did since the start.
    struct BeadRecord
    {
      double force      = 0; // N, restraining, summed along the line
      double opening    = 0; // N, taken from the holder's force
      double power      = 0; // N mm/s, restraining work rate
      double drawn_rate = 0; // mm/s, mean speed of material across it
      double work       = 0; // N mm since the start
      double drawn      = 0; // mm of material drawn across since the start
    };

    struct HolderState
    {
      bool   released       = false;
      double release_travel = -1; // punch travel at release (mm)
    };

    /// What a failed step may have changed, for step control.
    struct StepSnapshot
    {
      VectorType            velocity;
      contact::ContactState contact_state;
      std::vector<double>   control_velocities;
    };

    /// The model's own constraints on a vector field of @p dof_handler: no
    /// component normal to a symmetry plane, no radial one on the axis
    /// (the velocity of a step, the displacement of the springback).
    template <int dim>
    void add_model_constraints(const model::Model                 m,
                               const dealii::Mapping<dim>        &reference,
                               const dealii::DoFHandler<dim>     &dof_handler,
                               dealii::AffineConstraints<double> &constraints);

    template <int dim>
    struct State
    {
      State(const parameters::Run &run, const MPI_Comm comm);

      /// The blank mesh of Geometry and Mesh, then setup_dofs().
      void create_mesh();
      /// DoFs, constraints (hanging nodes, symmetry planes, axis), vectors,
      /// mapping, history entries (at the points of history_rule), contact
      /// nodes and a fresh contact state for the current mesh (after creation
      /// or adaptation).
      void setup_dofs();
      /// The mapping's support points from the displacement: after every
      /// change of it.
      void update_mapping();
      /// Contact nodal areas in the current configuration.
      void update_contact_areas();

      /// After a converged step of @p dt: history, geometry, tools, time.
      /// @p frames: the point frames of the step's configuration, if at
      /// hand (the forming system's).
      void advance(const double                      dt,
                   const HistoryUpdate<dim>         &update,
                   const material::PointFrames<dim> *frames = nullptr);

      StepSnapshot snapshot() const;
      void         restore(const StepSnapshot &s);

      /// The fields a mesh change or a checkpoint must carry, as ghosted
      /// nodal vectors: velocity, displacement, and the contact state (per
      /// tool: last factor, strict scale, multiplier and status, at each
      /// contact node's first DoF).
      std::vector<VectorType> transferable_fields() const;
      /// Their number.
      unsigned int n_transferable_fields() const
      {
        return 2 + record_fields * tools.size();
      }
      static constexpr unsigned int record_fields = 4;
      /// Takes the fields of transferable_fields() (locally owned vectors on
      /// the current mesh, after setup_dofs()) back.
      void set_transferable_fields(const std::vector<VectorType> &fields);

      /// The part at rest in the shape @p shape (a displacement on the
      /// current DoFs, owned; an earlier run's end), with a fresh contact
      /// state (after setup_dofs()).
      void set_shape(const VectorType &shape);

      /// Largest lateral distance (mm) of any sheet surface node from the
      /// edge of tool @p t's face (positive: on the face's side), all ranks.
      double max_lateral_distance(const unsigned int t) const;
      /// Smallest signed distance (mm) to tool @p t of the sheet surface
      /// nodes whose surface faces it (those that can carry its load), all
      /// ranks.
      double min_distance(const unsigned int t) const;
      /// The force control of tool @p t, or nullptr.
      ForceControl *force_control(const unsigned int t);
      /// Each control's target at @p punch_travel (the end of the step):
      /// its tool's force curve (a cushion curve, or constant), the
      /// model's share.
      void                set_force_targets(const double punch_travel);
      const ForceControl *force_control(const unsigned int t) const;
      /// The velocities and the activity of the force controls.
      std::vector<double> control_velocities() const;
      std::vector<bool>   active_controls() const;

      const parameters::Run &prm;
      MPI_Comm               comm;
      model::Kinematics<dim> kinematics;

      dealii::parallel::distributed::Triangulation<dim> tria;
      dealii::FESystem<dim>                             fe;
      dealii::DoFHandler<dim>                           dof_handler;
      /// The material points: where the history lives and the deviatoric
      /// stress is integrated (Gauss, degree + 1 points per direction).
      const dealii::QGauss<dim>         history_rule;
      dealii::IndexSet                  owned, relevant;
      dealii::AffineConstraints<double> constraints;
      dealii::MappingQ<dim>             reference_mapping;
      /// The current configuration (reference mapping + displacement),
      /// refreshed by update_mapping().
      std::unique_ptr<model::CurrentMapping<dim>> mapping;

      VectorType          velocity, displacement;             // owned
      VectorType          velocity_ghost, displacement_ghost; // ghosted
      HistoryStorage<dim> history;

      tools::ToolSet<dim> tools;
      contact::ContactSet<dim>
                            contact_set; // nodes; pairs of the accepted iterate
      contact::ContactState contact_state;
      std::vector<ForceControl> force_controls;
      HolderState               holder;
      std::vector<BeadRecord>   beads; // Tools/Draw beads, in order

      double       time = 0;
      unsigned int step = 0;
    };
  } // namespace state
} // namespace formsolve
