#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <formsolve/output/vtu_writer.h>

#include <fstream>

namespace formsolve
{
  namespace output
  {
    using namespace dealii;

    template <int dim>
    VtuWriter<dim>::VtuWriter(const std::string &directory)
        : directory(directory)
    {}

    template <int dim>
    void VtuWriter<dim>::write(const unsigned int       step,
                               const double             time,
                               const DoFHandler<dim>   &dof_handler,
                               const Mapping<dim>      &mapping,
                               const OutputFields<dim> &fields)
    {
      const auto  &tria = dof_handler.get_triangulation();
      DataOut<dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector_field(dim,
                     DataComponentInterpretation::component_is_part_of_vector),
        scalars(dim, DataComponentInterpretation::component_is_scalar);
      data_out.add_data_vector(*fields.velocity,
                               std::vector<std::string>(dim, "velocity"),
                               DataOut<dim>::type_dof_data,
                               vector_field);
      data_out.add_data_vector(*fields.displacement,
                               std::vector<std::string>(dim, "displacement"),
                               DataOut<dim>::type_dof_data,
                               vector_field);
      std::vector<std::string> contact_names = {"contact_gap",
                                                "contact_pressure",
                                                "penalty_factor"};
      contact_names.resize(dim, "unused");
      data_out.add_data_vector(*fields.contact,
                               contact_names,
                               DataOut<dim>::type_dof_data,
                               scalars);

      // Cell averages of the quadrature-point history.
      const unsigned int n = tria.n_active_cells();
      Vector<float> strain(n), rate(n), flow(n), mean(n), thick(n), rank(n);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto   h = fields.history->get_data(cell);
            const auto   i = cell->active_cell_index();
            const double w = 1. / h.size();
            for (const auto &p : h)
              {
                strain[i] += w * p->strain;
                rate[i] += w * p->strain_rate;
                flow[i] += w * p->flow_stress;
                mean[i] += w * p->mean_stress;
                thick[i] += w * p->thickness_strain;
              }
            rank[i] = tria.locally_owned_subdomain();
          }
      data_out.add_data_vector(strain, "equivalent_strain");
      data_out.add_data_vector(rate, "equivalent_strain_rate");
      data_out.add_data_vector(flow, "flow_stress");
      data_out.add_data_vector(mean, "mean_stress");
      data_out.add_data_vector(thick, "thickness_strain");
      data_out.add_data_vector(rank, "mpi_rank");
      data_out.build_patches(mapping,
                             dof_handler.get_fe().degree,
                             DataOut<dim>::curved_inner_cells);

      const MPI_Comm    comm = tria.get_communicator();
      const std::string pvtu =
        data_out.write_vtu_with_pvtu_record(directory + "/",
                                            "solution",
                                            step,
                                            comm,
                                            5,
                                            0);
      records.emplace_back(time, pvtu);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::ofstream pvd(directory + "/solution.pvd");
          DataOutBase::write_pvd_record(pvd, records);
        }
    }

    template class VtuWriter<3>;
  } // namespace output
} // namespace formsolve
