// The time loop: tools advance, Newton solves the step, the state advances,
// history and output are written.
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/lac/affine_constraints.h>

#include <formsolve/contact/contact_postprocessor.h>
#include <formsolve/contact/penalty_estimator.h>
#include <formsolve/material/rigid_viscoplastic.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/simulation/history_file.h>
#include <formsolve/simulation/mesh_refinement.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/linear_solver.h>
#include <formsolve/solver/newton_solver.h>
#include <formsolve/tools/tool_set.h>

#include <memory>

namespace formsolve
{
  namespace simulation
  {
    /// Summary of a finished run (for tests and benchmarks).
    struct RunSummary
    {
      unsigned int steps             = 0;
      unsigned int newton_iterations = 0;
      unsigned int linear_iterations = 0;
      double       wall_time         = 0;
      double       newton_wall_time  = 0; // spent inside Newton iterations
      double       n_dofs            = 0; // largest over the run
      double       dof_steps         = 0; // sum over steps of the DoFs
      double       peak_memory_kb = 0; // peak resident set, summed over ranks
    };

    template <int dim>
    class Simulation : private solver::NonlinearSystem
    {
    public:
      Simulation(const parameters::Run          &run,
                 const dealii::ParameterHandler &prm);

      /// Set up, check the scene, create the output folder, run all steps.
      /// Throws with a clear message when a step fails.
      RunSummary run();

      /// Build the mesh and check the initial scene, then stop (--validate).
      void validate_scene();

    private:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      void setup_mesh_and_dofs();
      /// DoFs, constraints, matrix, vectors, mapping and contact nodes of the
      /// current mesh (after creation or adaptation).
      void setup_dofs();
      /// Refine and coarsen by the Mesh refinement criteria, carrying the
      /// velocity, displacement and history over; logs a row of
      /// refinement.csv. Returns whether the mesh changed.
      bool adapt_mesh(const unsigned int step);
      void check_initial_scene();
      void prepare_output_directory();
      void write_output(const unsigned int step);
      void fill_contact_fields();
      /// Penalty factors from the body system (r_b, K_b) of the current pairs.
      void estimate_penalty(const VectorType         &r_b,
                            const solver::MatrixType &K_b);
      /// Contact forces and stiffness with the current factors, added to the
      /// matrix and residual (tangent type of the last assembly).
      void add_contact_terms();

      // solver::NonlinearSystem
      double       assemble(const VectorType &v, const bool newton) override;
      double       force_scale() const override { return f_scale; }
      unsigned int solve(VectorType &dv) override;
      double       residual_dot(const VectorType &w) const override
      {
        return residual * w;
      }
      bool        contact_set_changed() override;
      double      update_penalty() override;
      std::string iteration_info() const override
      {
        return estimator->summary();
      }

      const parameters::Run          &prm;
      const dealii::ParameterHandler &parameter_handler;
      MPI_Comm                        comm;
      dealii::ConditionalOStream      pcout;
      dealii::TimerOutput             timer;

      dealii::parallel::distributed::Triangulation<dim> tria;
      dealii::FESystem<dim>                             fe;
      dealii::DoFHandler<dim>                           dof_handler;
      dealii::IndexSet                                  owned, relevant;
      dealii::AffineConstraints<double>                 constraints;
      dealii::MappingQ<dim>                             reference_mapping;
      std::unique_ptr<dealii::MappingQEulerian<dim, VectorType>> mapping;

      solver::MatrixType matrix;
      /// Body system (no contact) of the last assembly, kept for adaptive
      /// penalty estimates at accepted iterates.
      solver::MatrixType body_matrix;
      VectorType         body_residual;
      VectorType         residual, velocity, velocity_ghost, displacement,
        displacement_ghost, contact_fields;

      material::RigidViscoplastic<dim>                material;
      solver::Assembler<dim>                          assembler;
      solver::HistoryStorage<dim>                     history;
      tools::ToolSet<dim>                             tools;
      contact::ContactPostprocessor<dim>              contact_post;
      contact::ContactSet<dim>                        contact_set;
      std::unique_ptr<contact::PenaltyEstimator<dim>> estimator;
      std::vector<double>                             epsilon;
      std::vector<bool>                               last_active;
      std::unique_ptr<solver::LinearSolver>           linear_solver;
      RefinementCriteria<dim>                         refinement;
      std::unique_ptr<HistoryFile>                    refinement_log;

      double dt          = 0;
      double f_scale     = 0;
      bool   last_newton = true; // tangent type of the last assembly
      // Per step: largest linear iteration count and condition estimate.
      unsigned int step_max_linear_iterations = 0;
      double       step_condition             = 0;
    };
  } // namespace simulation
} // namespace formsolve
