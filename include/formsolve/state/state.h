// What a step changes, in one object: mesh, DoFs, velocity, displacement,
// quadrature history, tool positions, contact nodes and contact state, the
// blank-holder control and the time. Refinement transfers it as one; step
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

    /// The blank holder's control: force control until the blank has left
    /// it.
    struct HolderState
    {
      bool   force_control  = false; // Control = force and not released
      bool   released       = false;
      double velocity       = 0;  // axial velocity of the last step (mm/s)
      double target         = 0;  // set force on the modelled part (N)
      double release_travel = -1; // punch travel at release (mm)
    };

    /// What a failed step may have changed, for step control.
    struct StepSnapshot
    {
      VectorType            velocity;
      contact::ContactState contact_state;
      double                holder_velocity;
    };

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
      void advance(const double dt, const HistoryUpdate<dim> &update);

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

      /// Largest lateral distance (mm) of any sheet surface node from the
      /// edge of tool @p t's face (positive: on the face's side), all ranks.
      double max_lateral_distance(const unsigned int t) const;
      /// Smallest signed distance (mm) to tool @p t of the sheet surface
      /// nodes whose surface faces it (those that can carry its load), all
      /// ranks.
      double min_distance(const unsigned int t) const;

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

      tools::ToolSet<dim>      tools;
      contact::ContactSet<dim> contact_set; // nodes; pairs of the last iterate
      contact::ContactState    contact_state;
      HolderState              holder;

      double       time = 0;
      unsigned int step = 0;
    };
  } // namespace state
} // namespace formsolve
