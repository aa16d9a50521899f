#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/revolved_output.h>
#include <formsolve/postprocess/vtu_writer.h>

#include <fstream>
#include <memory>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /// zlib's fastest level: with the default best compression, output
      /// took a third of the default cup's run (measured 11.9 s -> 8.3 s),
      /// for files about a fifth larger.
      DataOutBase::VtkFlags fast()
      {
        DataOutBase::VtkFlags flags;
        flags.compression_level = DataOutBase::VtkFlags::best_speed;
        return flags;
      }

      /// One component of a vector-valued nodal field, as a named scalar.
      template <int dim>
      class Component : public DataPostprocessorScalar<dim>
      {
      public:
        Component(const std::string &name, const unsigned int c)
            : DataPostprocessorScalar<dim>(name, update_values)
            , c(c)
        {}
        void
        evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &in,
                              std::vector<Vector<double>> &out) const override
        {
          for (unsigned int q = 0; q < out.size(); ++q)
            out[q](0) = in.solution_values[q](c);
        }

      private:
        unsigned int c;
      };

      /// Axis @p axis (0: RD, 2: ND) of the orthotropy frame, from the
      /// displacement's gradient in the current configuration: F = (I -
      /// grad u)^-1.
      template <int dim>
      class FrameAxis : public DataPostprocessorVector<dim>
      {
      public:
        FrameAxis(const std::string               &name,
                  const unsigned int               axis,
                  const model::MaterialFrame<dim> &frame)
            : DataPostprocessorVector<dim>(name, update_gradients)
            , axis(axis)
            , frame(frame)
        {}
        void
        evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &in,
                              std::vector<Vector<double>> &out) const override
        {
          for (unsigned int q = 0; q < out.size(); ++q)
            {
              Tensor<2, dim> inverse_F = unit_symmetric_tensor<dim>();
              for (unsigned int i = 0; i < dim; ++i)
                inverse_F[i] -= in.solution_gradients[q][i];
              const Tensor<2, 3> R = frame(invert(inverse_F));
              for (unsigned int d = 0; d < dim; ++d)
                out[q](d) = R[d][axis];
            }
        }

      private:
        unsigned int                     axis;
        const model::MaterialFrame<dim> &frame;
      };

      /// Adds the fields of @p f to @p out; cell averages of the history go
      /// to @p cell_data, which must outlive the patches.
      template <int dim, class DataOutType>
      void add_fields(DataOutType                                  &out,
                      const DoFHandler<dim>                        &dof_handler,
                      const OutputFields<dim>                      &f,
                      std::vector<Vector<float>>                   &cell_data,
                      std::vector<std::unique_ptr<Component<dim>>> &scalars,
                      std::vector<std::unique_ptr<FrameAxis<dim>>> &axes)
      {
        out.attach_dof_handler(dof_handler);
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          vector_field(
            dim,
            DataComponentInterpretation::component_is_part_of_vector);
        out.add_data_vector(*f.velocity,
                            std::vector<std::string>(dim, "velocity"),
                            DataOut<dim>::type_dof_data,
                            vector_field);
        out.add_data_vector(*f.displacement,
                            std::vector<std::string>(dim, "displacement"),
                            DataOut<dim>::type_dof_data,
                            vector_field);
        for (const auto &s : f.nodal)
          {
            scalars.push_back(
              std::make_unique<Component<dim>>(s.name, s.component));
            out.add_data_vector(*s.values, *scalars.back());
          }
        if (f.frame)
          for (const auto &[name, axis] :
               {std::pair<const char *, unsigned int>{"rolling_direction", 0},
                {"normal_direction", 2}})
            {
              axes.push_back(
                std::make_unique<FrameAxis<dim>>(name, axis, *f.frame));
              out.add_data_vector(*f.displacement, *axes.back());
            }

        // Cell averages of the quadrature-point history.
        const auto        &tria = dof_handler.get_triangulation();
        const unsigned int n    = tria.n_active_cells();
        // The history values, then the rank.
        std::vector<std::string> names =
          state::QuadraturePointHistory::value_names();
        names.push_back("mpi_rank");
        const unsigned int nh = names.size() - 1;
        cell_data.assign(names.size(), Vector<float>(n));
        std::vector<double> values;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const auto   h = f.history->get_data(cell);
              const auto   i = cell->active_cell_index();
              const double w = 1. / h.size();
              for (const auto &p : h)
                {
                  p->pack_values(values);
                  Assert(values.size() == nh, ExcInternalError());
                  for (unsigned int k = 0; k < nh; ++k)
                    cell_data[k][i] += w * values[k];
                }
              cell_data[nh][i] = tria.locally_owned_subdomain();
            }
        for (unsigned int k = 0; k < names.size(); ++k)
          out.add_data_vector(cell_data[k], names[k]);
        for (const auto &[name, values] : f.cell)
          out.add_data_vector(*values, name);
      }
    } // namespace

    template <int dim>
    void select_cells(
      DataOut<dim> &out,
      const std::function<
        bool(const typename Triangulation<dim>::active_cell_iterator &)> &part)
    {
      using Cell   = typename Triangulation<dim>::cell_iterator;
      using Active = typename Triangulation<dim>::active_cell_iterator;
      // The first selected cell from @p it on, or the end.
      const auto from = [part](const Triangulation<dim> &tria, Active it) {
        while (it != tria.end() && !(it->is_locally_owned() && part(it)))
          ++it;
        return it == tria.end() ? tria.end() : Cell(it);
      };
      out.set_cell_selection(
        [from](const Triangulation<dim> &tria) {
          return from(tria, tria.begin_active());
        },
        [from](const Triangulation<dim> &tria, const Cell &cell) {
          Active next(cell);
          return from(tria, ++next);
        });
    }

    template <int dim>
    VtuWriter<dim>::VtuWriter(const parameters::Output &p)
        : prm(p)
    {}

    template <int dim>
    void VtuWriter<dim>::write(const unsigned int       step,
                               const double             time,
                               const DoFHandler<dim>   &dof_handler,
                               const Mapping<dim>      &mapping,
                               const OutputFields<dim> &fields,
                               const bool               section,
                               const bool               revolved)
    {
      const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
      const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
      if (section)
        {
          DataOut<dim>                                 out;
          std::vector<Vector<float>>                   cell_data;
          std::vector<std::unique_ptr<Component<dim>>> scalars;
          std::vector<std::unique_ptr<FrameAxis<dim>>> axes;
          add_fields(out, dof_handler, fields, cell_data, scalars, axes);
          out.set_flags(fast());
          out.build_patches(mapping,
                            dof_handler.get_fe().degree,
                            DataOut<dim>::curved_inner_cells);
          records.emplace_back(
            time,
            write_vtu_atomically(out, prm.directory, "solution", step, comm));
          if (root)
            {
              write_atomically(prm.directory + "/solution.pvd",
                               [&](std::ostream &f) {
                                 DataOutBase::write_pvd_record(f, records);
                               });
            }
        }
      if constexpr (dim == 2)
        if (revolved)
          {
            // One subdivision, no curved cells: the patch vertices are the
            // deformed ones, which the revolution needs.
            SectionDataOut                             out;
            std::vector<Vector<float>>                 cell_data;
            std::vector<std::unique_ptr<Component<2>>> scalars;
            std::vector<std::unique_ptr<FrameAxis<2>>> axes;
            add_fields(out, dof_handler, fields, cell_data, scalars, axes);
            out.set_flags(fast());
            out.build_patches(mapping, 1, DataOut<2>::no_curved_cells);
            revolved_records.emplace_back(time,
                                          write_revolved(out,
                                                         prm.revolved_angle,
                                                         prm.directory,
                                                         step,
                                                         comm));
            if (root)
              {
                write_atomically(
                  prm.directory + "/revolved.pvd",
                  [&](std::ostream &f) {
                    DataOutBase::write_pvd_record(f, revolved_records);
                  });
              }
          }
    }

    template <int dim>
    std::string VtuWriter<dim>::write_part(
      const unsigned int       step,
      const DoFHandler<dim>   &dof_handler,
      const Mapping<dim>      &mapping,
      const OutputFields<dim> &fields,
      const std::function<
        bool(const typename Triangulation<dim>::active_cell_iterator &)> &part,
      const std::string &base) const
    {
      DataOut<dim>                                 out;
      std::vector<Vector<float>>                   cell_data;
      std::vector<std::unique_ptr<Component<dim>>> scalars;
      std::vector<std::unique_ptr<FrameAxis<dim>>> axes;
      add_fields(out, dof_handler, fields, cell_data, scalars, axes);
      select_cells(out, part);
      out.set_flags(fast());
      out.build_patches(mapping,
                        dof_handler.get_fe().degree,
                        DataOut<dim>::curved_inner_cells);
      return write_vtu_atomically(out,
                                  prm.directory,
                                  base,
                                  step,
                                  dof_handler.get_communicator());
    }

#define INSTANTIATE(dim)         \
  template class VtuWriter<dim>; \
  template void select_cells(    \
    DataOut<dim> &,              \
    const std::function<bool(    \
      const typename Triangulation<dim>::active_cell_iterator &)> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
