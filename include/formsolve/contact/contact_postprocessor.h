// Finds the sheet surface nodes near each tool and measures contact:
// gaps, normals, status, nodal areas, forces per tool, penetration statistics.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/tools/tool_set.h>

#include <vector>

namespace formsolve
{
  namespace contact
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// Per-tool and overall contact measures (summed over all ranks).
    template <int dim>
    struct ContactStatistics
    {
      std::vector<Tensor<1, dim>>
                          tool_force; // force of the sheet on each tool (N)
      std::vector<double> tool_max_penetration; // mm, per tool, >= 0
      double              max_penetration  = 0; // mm, >= 0
      double              mean_penetration = 0; // mm, over active pairs
      unsigned int        n_active         = 0;
      unsigned int        n_over_allowed = 0; // active pairs deeper than delta
      unsigned int        n_locked       = 0; // pairs whose status was locked
    };

    template <int dim>
    class ContactPostprocessor
    {
    public:
      /// A pair whose status changes @p max_status_flips times in a step keeps
      /// its status for the rest of the step (chatter guard).
      ContactPostprocessor(const double       search_distance,
                           const double       regularisation_velocity,
                           const unsigned int max_status_flips = 1000000);

      /// Collect the locally owned nodes on faces with the free-surface id.
      void setup(const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &reference_mapping,
                 ContactSet<dim>               &set) const;

      /// Lumped nodal area vectors in the configuration given by @p mapping.
      void update_areas(const dealii::DoFHandler<dim> &dof_handler,
                        const dealii::Mapping<dim>    &mapping,
                        ContactSet<dim>               &set) const;

      /// Gaps at the current positions (X + displacement) and predicted gaps
      /// after moving with @p velocity for @p dt. Vectors must be ghosted.
      void evaluate(const tools::ToolSet<dim> &tools,
                    const VectorType          &displacement,
                    const VectorType          &velocity,
                    const double               dt,
                    ContactSet<dim>           &set) const;

      /// Forces from the contact law with factors @p epsilon (one per pair),
      /// and penetration statistics of the predicted (end-of-step) gaps.
      ContactStatistics<dim> statistics(const tools::ToolSet<dim> &tools,
                                        const ContactSet<dim>     &set,
                                        const std::vector<double> &epsilon,
                                        const double               dt,
                                        const MPI_Comm             comm) const;

      double regularisation_velocity() const { return v0; }

    private:
      double       search_distance;
      double       v0;
      unsigned int max_status_flips;
    };
  } // namespace contact
} // namespace formsolve
