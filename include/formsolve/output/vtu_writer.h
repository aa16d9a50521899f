// VTU/PVTU files on the deformed mesh and the PVD time series.
#pragma once

#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/simulation/quadrature_history.h>

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace output
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    template <int dim>
    struct OutputFields
    {
      const VectorType *velocity     = nullptr; // ghosted
      const VectorType *displacement = nullptr; // ghosted
      /// Nodal contact fields: component 0 gap, 1 pressure, 2 penalty factor.
      const VectorType *contact = nullptr; // ghosted
      const dealii::CellDataStorage<
        typename dealii::Triangulation<dim>::cell_iterator,
        simulation::QuadraturePointHistory> *history = nullptr;
    };

    template <int dim>
    class VtuWriter
    {
    public:
      explicit VtuWriter(const std::string &directory);

      /// Writes solution_<step>.vtu/.pvtu and rewrites solution.pvd.
      void write(const unsigned int             step,
                 const double                   time,
                 const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &mapping,
                 const OutputFields<dim>       &fields);

    private:
      std::string                                 directory;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace output
} // namespace formsolve
