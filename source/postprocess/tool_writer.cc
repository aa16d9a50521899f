#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/tool_writer.h>


namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    template <int dim>
    ToolWriter<dim>::ToolWriter(const std::string &directory)
        : directory(directory)
    {}

    template <int dim>
    void ToolWriter<dim>::write(const unsigned int          step,
                                const double                time,
                                const tools::ToolSet<dim>  &tools,
                                const tools::SurfaceExtent &extent,
                                const MPI_Comm              comm)
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      // One patch per cell, without subdivisions: the surfaces are drawn
      // as they are, and every cell carries its tool's index.
      std::vector<DataOutBase::Patch<dim - 1, dim>> patches;
      for (unsigned int t = 0; t < tools.size(); ++t)
        {
          const auto surface = tools[t].surface(extent);
          for (const auto &cell : surface.cells)
            {
              DataOutBase::Patch<dim - 1, dim> patch;
              patch.reference_cell = ReferenceCells::get_hypercube<dim - 1>();
              patch.n_subdivisions = 1;
              patch.patch_index    = patches.size();
              for (unsigned int v = 0; v < cell.size(); ++v)
                patch.vertices[v] = surface.points[cell[v]];
              patch.data.reinit(1, cell.size());
              for (unsigned int v = 0; v < cell.size(); ++v)
                patch.data(0, v) = t;
              patches.push_back(patch);
            }
          if constexpr (dim == 3)
            for (const auto &triangle : surface.triangles)
              {
                DataOutBase::Patch<2, 3> patch;
                patch.reference_cell = ReferenceCells::Triangle;
                patch.n_subdivisions = 1;
                patch.patch_index    = patches.size();
                for (unsigned int v = 0; v < 3; ++v)
                  patch.vertices[v] = surface.points[triangle[v]];
                patch.data.reinit(1, 3);
                for (unsigned int v = 0; v < 3; ++v)
                  patch.data(0, v) = t;
                patches.push_back(patch);
              }
        }
      const std::string name =
        "tools_" + Utilities::int_to_string(step, 5) + ".vtu";
      DataOutBase::VtkFlags flags;
      flags.time  = time;
      flags.cycle = step;
      write_atomically(directory + "/" + name, [&](std::ostream &f) {
        DataOutBase::write_vtu(patches, {"tool"}, {}, flags, f);
      });
      records.emplace_back(time, name);
      write_atomically(directory + "/tools.pvd", [&](std::ostream &f) {
        DataOutBase::write_pvd_record(f, records);
      });
    }

#define INSTANTIATE(dim) template class ToolWriter<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
