// VTU/PVTU files on the deformed mesh and the PVD time series; for the
// axisymmetric model optionally also the section revolved about the z axis.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <formsolve/model/material_frame.h>
#include <formsolve/parameters/output.h>
#include <formsolve/state/quadrature_history.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// A nodal scalar stored as component @p component of a ghosted vector
    /// on the velocity DoFHandler.
    struct NodalScalar
    {
      std::string       name;
      const VectorType *values    = nullptr;
      unsigned int      component = 0;
    };

    template <int dim>
    struct OutputFields
    {
      const VectorType                 *velocity     = nullptr; // ghosted
      const VectorType                 *displacement = nullptr; // ghosted
      std::vector<NodalScalar>          nodal;
      const state::HistoryStorage<dim> *history = nullptr;
      /// Cell fields by active cell index (name, values).
      std::vector<std::pair<std::string, const dealii::Vector<float> *>> cell;
      /// With it, the orthotropy axes RD and ND as vector fields.
      const model::MaterialFrame<dim> *frame = nullptr;
    };

    /// Which active cells are written: @p out writes the locally owned
    /// ones @p part selects.
    template <int dim>
    void
    select_cells(dealii::DataOut<dim>                                    &out,
                 const std::function<bool(const typename dealii::Triangulation<
                                          dim>::active_cell_iterator &)> &part);

    template <int dim>
    class VtuWriter
    {
    public:
      explicit VtuWriter(const parameters::Output &p);

      /// Writes solution_<step>.vtu/.pvtu and rewrites solution.pvd if
      /// @p section, the revolved copy (revolved.pvd) if @p revolved and
      /// dim = 2.
      void write(const unsigned int             step,
                 const double                   time,
                 const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &mapping,
                 const OutputFields<dim>       &fields,
                 const bool                     section,
                 const bool                     revolved);

      /// Writes <base>_<step>.pvtu of the locally owned cells @p part
      /// selects (a trimmed part), outside the time series; returns the
      /// file's name.
      std::string
      write_part(const unsigned int             step,
                 const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &mapping,
                 const OutputFields<dim>       &fields,
                 const std::function<bool(const typename dealii::Triangulation<
                                          dim>::active_cell_iterator &)> &part,
                 const std::string &base) const;
      /// The (time, file) records of solution.pvd and revolved.pvd, for
      /// checkpoints.
      using Records = std::vector<std::pair<double, std::string>>;
      const Records &solution_records() const { return records; }
      const Records &revolved_pvd_records() const { return revolved_records; }
      void set_records(const Records &solution, const Records &revolved)
      {
        records          = solution;
        revolved_records = revolved;
      }

    private:
      parameters::Output                          prm;
      std::vector<std::pair<double, std::string>> records, revolved_records;
    };
  } // namespace postprocess
} // namespace formsolve
