// Finds the sheet surface nodes near each tool and measures contact: gaps,
// normals, status, nodal areas (through the kinematics: full ring in
// axisymmetry).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/contact/contact_state.h>
#include <formsolve/model/kinematics.h>
#include <formsolve/tools/tool_set.h>

namespace formsolve
{
  namespace contact
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    template <int dim>
    class ContactSearch
    {
    public:
      explicit ContactSearch(const double search_distance);

      /// Collect the locally owned nodes on faces with the free-surface id.
      void setup(const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &reference_mapping,
                 ContactSet<dim>               &set) const;

      /// Lumped nodal area vectors in the configuration given by @p mapping.
      void update_areas(const dealii::DoFHandler<dim> &dof_handler,
                        const dealii::Mapping<dim>    &mapping,
                        const model::Kinematics<dim>  &kinematics,
                        ContactSet<dim>               &set) const;

      /// Gaps at the current positions (X + displacement) and predicted gaps
      /// after moving with @p velocity for @p dt, the tools at
      /// @p tool_velocities (one per tool, mm/s). Vectors must be ghosted.
      /// Multipliers (gap shifts) come from @p state.
      void evaluate(const tools::ToolSet<dim>         &tools,
                    const std::vector<Tensor<1, dim>> &tool_velocities,
                    const VectorType                  &displacement,
                    const VectorType                  &velocity,
                    const double                       dt,
                    const ContactState                &state,
                    ContactSet<dim>                   &set) const;

    private:
      double search_distance;
    };
  } // namespace contact
} // namespace formsolve
