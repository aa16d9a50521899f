// The element pressures averaged onto the nodes and interpolated: a
// continuous mean-stress field for the fracture integrals (Material/Fracture
// mean stress = projected; doc/theory.md, section 11b). Each node of the
// velocity's first component takes the lumped L2 projection
// p_i = sum_c p_c int phi_i dV / sum_c int phi_i dV over the cells around
// it; hanging nodes follow their masters.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/model/cell_kinematics.h>

#include <vector>

namespace formsolve
{
  namespace state
  {
    template <int dim>
    class ProjectedMeanStress
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /// From @p cell_values (MPa, by active cell index, set on the locally
      /// owned cells), weighted with the volumes of @p k; @p layout is a
      /// ghosted vector of @p dof_handler's partition (collective).
      void project(const dealii::DoFHandler<dim> &dof_handler,
                   model::CellKinematics<dim>    &k,
                   const std::vector<double>     &cell_values,
                   const VectorType              &layout);

      /// The field at the points of @p fv (reinitialised on a locally owned
      /// cell).
      void values(const dealii::FEValues<dim> &fv,
                  std::vector<double>         &out) const;

    private:
      VectorType field; // ghosted
    };
  } // namespace state
} // namespace formsolve
