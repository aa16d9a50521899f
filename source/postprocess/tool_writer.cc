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

    namespace
    {
      /// Bead @p b of @p beads as patches standing on the die face across
      /// the thickness @p t0: a quad per segment (3-D), a line (2-D).
      template <int dim>
      void add_bead(const parameters::DrawBead                    &bead,
                    const double                                   value,
                    const double                                   t0,
                    std::vector<DataOutBase::Patch<dim - 1, dim>> &patches)
      {
        const auto  &line    = bead.line;
        const double lift[2] = {0., t0};
        for (std::size_t i = 0; i < (dim == 2 ? 1 : line.size() - 1) +
                                      (dim == 3 && bead.closed ? 1 : 0);
             ++i)
          {
            DataOutBase::Patch<dim - 1, dim> patch;
            patch.reference_cell = ReferenceCells::get_hypercube<dim - 1>();
            patch.n_subdivisions = 1;
            patch.patch_index    = patches.size();
            const unsigned int n = 1u << (dim - 1);
            for (unsigned int v = 0; v < n; ++v)
              {
                const auto &p = line[dim == 2 ? 0 : (i + v % 2) % line.size()];
                patch.vertices[v][0]       = p.first;
                patch.vertices[v][dim - 1] = lift[dim == 2 ? v : v / 2];
                if (dim == 3)
                  patch.vertices[v][1] = p.second;
              }
            patch.data.reinit(1, n);
            for (unsigned int v = 0; v < n; ++v)
              patch.data(0, v) = value;
            patches.push_back(patch);
          }
      }
    } // namespace

    template <int dim>
    void ToolWriter<dim>::write(const unsigned int           step,
                                const double                 time,
                                const tools::ToolSet<dim>   &tools,
                                const tools::SurfaceExtent  &extent,
                                const parameters::DrawBeads &beads,
                                const double                 t0,
                                const MPI_Comm               comm)
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
      for (std::size_t b = 0; b < beads.beads.size(); ++b)
        add_bead<dim>(beads.beads[b], tools.size() + b, t0, patches);
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
