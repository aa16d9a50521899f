// How the part is held while it springs back: the minimal support, which
// removes exactly the rigid-body motions the model's symmetry planes leave
// (statically determinate: the release does not depend on it), or the
// points a user names; and the check that no rigid-body motion is left free.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <formsolve/model/model.h>
#include <formsolve/parameters/springback.h>
#include <formsolve/state/state.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace springback
  {
    /// A node held during the release.
    template <int dim>
    struct Support
    {
      dealii::Point<dim> node;       // current configuration (mm)
      std::string        components; // coordinate letters
    };

    /// The supports: @p user's points at their nearest nodes, or, if none,
    /// the minimal support of model @p m (3-2-1 for the full sheet, one
    /// node's z in the models with symmetry in x and y). Collective.
    template <int dim>
    std::vector<Support<dim>>
    choose_supports(const dealii::DoFHandler<dim>               &dof_handler,
                    const dealii::Mapping<dim>                  &mapping,
                    const model::Model                           m,
                    const std::vector<parameters::SupportPoint> &user);

    /// Adds the supports' zero displacements to @p constraints.
    template <int dim>
    void add_supports(const dealii::DoFHandler<dim>     &dof_handler,
                      const dealii::Mapping<dim>        &mapping,
                      const model::Model                 m,
                      const std::vector<Support<dim>>   &supports,
                      dealii::AffineConstraints<double> &constraints);

    /// The rigid-body motions of model @p m that the fixed DoFs of
    /// @p constraints leave free, in words ("translation along z, ..."),
    /// or empty. Collective.
    template <int dim>
    std::string free_rigid_motions(const dealii::DoFHandler<dim> &dof_handler,
                                   const dealii::Mapping<dim>    &mapping,
                                   const model::Model             m,
                                   const dealii::AffineConstraints<double> &c);

    /// The constraints of the release on @p dof_handler (a displacement on
    /// @p state's mesh, nodes placed by @p mapping): hanging nodes, the model's
    /// symmetry planes and axis (with @p slit, Springback/Slit's opening of
    /// the plane x = 0), and the supports of Springback/Supports; closed.
    /// Throws naming Springback/Supports if a rigid-body motion is left
    /// free (the same on every rank). Returns the supports.
    template <int dim>
    std::vector<Support<dim>>
    hold(const state::State<dim>           &state,
         const dealii::Mapping<dim>        &mapping,
         const dealii::DoFHandler<dim>     &dof_handler,
         dealii::AffineConstraints<double> &constraints,
         const bool                         slit);

    /// "z at (r 0, z -1.2); ..." for the run summary.
    template <int dim>
    std::string describe_supports(const std::vector<Support<dim>> &s,
                                  const model::Model               m);

    /// hold() on the current mesh with the release's element, before any
    /// work (the scene check).
    template <int dim>
    void check_supports(const state::State<dim> &state);
  } // namespace springback
} // namespace formsolve
