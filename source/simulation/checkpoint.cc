#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/distributed/solution_transfer.h>

#include <formsolve/app/error_exit.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/checkpoint.h>
#include <formsolve/simulation/parameter_listing.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;
    namespace fs = std::filesystem;

    namespace
    {
      using CellValues = std::vector<std::vector<double>>;

      template <int dim>
      std::string text(const Tensor<1, dim> &t)
      {
        std::ostringstream s;
        s.precision(17);
        for (unsigned int d = 0; d < dim; ++d)
          s << (d ? " " : "") << t[d];
        return s.str();
      }

      template <int dim>
      Tensor<1, dim> tensor(const std::string &text)
      {
        std::istringstream s(text);
        Tensor<1, dim>     t;
        for (unsigned int d = 0; d < dim; ++d)
          s >> t[d];
        return t;
      }

    } // namespace

    std::string exact_text(const double x)
    {
      std::ostringstream s;
      s.precision(17);
      s << x;
      return s.str();
    }

    template <int dim>
    Checkpoint<dim>::Checkpoint(const std::string &output_directory,
                                const std::string &parameters)
        : directory(output_directory)
        , parameters(parameters)
    {}

    template <int dim>
    void Checkpoint<dim>::save(const State<dim>        &state,
                               const Metadata          &meta,
                               const VectorType        *sprung,
                               const std::vector<bool> *kept) const
    {
      const bool root = Utilities::MPI::this_mpi_process(state.comm) == 0;
      const std::string fresh = directory + "/checkpoint.new",
                        done  = directory + "/checkpoint",
                        old   = directory + "/checkpoint.old";
      if (root)
        {
          fs::remove_all(fresh);
          fs::create_directories(fresh);
        }
      MPI_Barrier(state.comm);

      // Fields and history attached to the mesh, in this order on loading.
      parallel::distributed::SolutionTransfer<dim, VectorType> fields(
        state.dof_handler);
      auto values = state.transferable_fields();
      if (sprung)
        {
          values.emplace_back(state.owned, state.relevant, state.comm);
          values.back() = *sprung;
        }
      std::vector<const VectorType *> in;
      for (const auto &v : values)
        in.push_back(&v);
      fields.prepare_for_serialization(in);
      CellValues          history(state.tria.n_active_cells());
      std::vector<double> packed;
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &q : state.history.get_data(cell))
            {
              q->pack_values(packed);
              auto &h = history[cell->active_cell_index()];
              h.insert(h.end(), packed.begin(), packed.end());
            }
      // A trimmed part: each cell's side of the cut after its history.
      if (kept)
        for (const auto &cell : state.tria.active_cell_iterators())
          if (cell->is_locally_owned())
            history[cell->active_cell_index()].push_back(
              (*kept)[cell->active_cell_index()] ? 1 : 0);
      parallel::distributed::CellDataTransfer<dim, dim, CellValues> cells(
        state.tria,
        /*variable size*/ true);
      cells.prepare_for_serialization(history);
      state.tria.save(fresh + "/mesh");
      app::injected_kill("checkpoint", state.step);

      if (root)
        {
          Metadata all        = meta;
          all["time"]         = exact_text(state.time);
          all["step"]         = std::to_string(state.step);
          all["coarse_cells"] = std::to_string(state.tria.n_cells(0));
          all["fields"]       = std::to_string(values.size());
          all["sprung"]       = sprung ? "1" : "0";
          all["trimmed"]      = kept ? "1" : "0";
          for (unsigned int t = 0; t < state.tools.size(); ++t)
            {
              const auto key         = "tool." + std::to_string(t);
              all[key + ".position"] = text<dim>(state.tools[t].displacement());
              all[key + ".travel"]   = exact_text(state.tools[t].travel());
              all[key + ".velocity"] = text<dim>(state.tools[t].velocity());
            }
          for (const auto &f : state.force_controls)
            {
              const auto key         = "control." + std::to_string(f.tool);
              all[key + ".active"]   = std::to_string(f.active);
              all[key + ".velocity"] = exact_text(f.velocity);
            }
          // What the draw beads did so far (their rates are the next step's).
          for (std::size_t b = 0; b < state.beads.size(); ++b)
            {
              const auto key      = "bead." + std::to_string(b);
              all[key + ".work"]  = exact_text(state.beads[b].work);
              all[key + ".drawn"] = exact_text(state.beads[b].drawn);
            }
          all["holder.released"] = std::to_string(state.holder.released);
          all["holder.release_travel"] =
            exact_text(state.holder.release_travel);
          std::ofstream m(fresh + "/meta.txt");
          for (const auto &[k, v] : all)
            m << k << " = " << v << '\n';
          std::ofstream(fresh + "/parameters.prm") << parameters;
          m.close();
          std::ofstream(fresh + "/complete") << "complete\n";
        }
      MPI_Barrier(state.comm);
      if (root)
        {
          fs::remove_all(old);
          if (fs::exists(done))
            fs::rename(done, old);
          fs::rename(fresh, done);
          fs::remove_all(old);
        }
      MPI_Barrier(state.comm);
    }

    std::string newest_checkpoint(const std::string &directory)
    {
      // A save interrupted after its rename step leaves checkpoint.new or
      // checkpoint.old complete.
      for (const auto *name :
           {"checkpoint", "checkpoint.new", "checkpoint.old"})
        if (fs::exists(directory + "/" + name + "/complete"))
          return directory + "/" + name;
      return "";
    }

    Metadata read_metadata(const std::string &from)
    {
      Metadata      meta;
      std::ifstream m(from + "/meta.txt");
      std::string   line;
      while (std::getline(m, line))
        {
          const auto eq = line.find(" = ");
          if (eq != std::string::npos)
            meta[line.substr(0, eq)] = line.substr(eq + 3);
        }
      return meta;
    }

    std::string read_parameters(const std::string &from)
    {
      std::ifstream      p(from + "/parameters.prm");
      std::ostringstream saved;
      saved << p.rdbuf();
      return saved.str();
    }

    template <int dim>
    std::vector<VectorType> load_part(const std::string &from,
                                      const Metadata    &meta,
                                      State<dim>        &state,
                                      const std::string &who,
                                      std::vector<bool> *kept)
    {
      geometry::create_coarse_blank_mesh(state.prm.geometry,
                                         state.prm.mesh,
                                         state.tria);
      AssertThrow(meta.count("coarse_cells") &&
                    std::stoul(meta.at("coarse_cells")) ==
                      state.tria.n_cells(0),
                  ExcMessage(who + ": the checkpoint in " + from +
                             " was written by a formsolve with another "
                             "coarse mesh; start the run again"));
      state.tria.load(from + "/mesh");
      state.setup_dofs();
      parallel::distributed::SolutionTransfer<dim, VectorType> fields(
        state.dof_handler);
      std::vector<VectorType>   values(std::stoul(meta.at("fields")),
                                     VectorType(state.owned, state.comm));
      std::vector<VectorType *> out;
      for (auto &v : values)
        out.push_back(&v);
      fields.deserialize(out);
      CellValues history(state.tria.n_active_cells());
      parallel::distributed::CellDataTransfer<dim, dim, CellValues> cells(
        state.tria,
        true);
      cells.deserialize(history);
      const bool trimmed = meta.count("trimmed") && meta.at("trimmed") == "1";
      if (kept)
        kept->assign(state.tria.n_active_cells(), true);
      for (const auto &cell : state.tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &h = history[cell->active_cell_index()];
            auto        q = state.history.get_data(cell);
            const auto  n = q[0]->number_of_values();
            if (kept && trimmed && !h.empty())
              (*kept)[cell->active_cell_index()] = h.back() > 0.5;
            AssertThrow(h.size() == n * q.size() + (trimmed ? 1 : 0),
                        ExcMessage(who + ": the checkpoint in " + from +
                                   " does not fit this program's history "
                                   "data"));
            for (unsigned int i = 0; i < q.size(); ++i)
              q[i]->unpack_values(std::vector<double>(h.begin() + i * n,
                                                      h.begin() + (i + 1) * n));
          }
      return values;
    }

    template <int dim>
    Metadata Checkpoint<dim>::load(State<dim> &state) const
    {
      const std::string from = newest_checkpoint(directory);
      AssertThrow(!from.empty(),
                  ExcMessage("--resume: there is no complete checkpoint in " +
                             directory + " (Output/Checkpoint interval)"));
      const std::string saved = read_parameters(from);
      AssertThrow(without_output(saved) == without_output(parameters),
                  ExcMessage("--resume: the checkpoint in " + from +
                             " was written by another case; its parameters (" +
                             from + "/parameters.prm) differ from these: " +
                             differences(saved, parameters, "the checkpoint") +
                             " (only Output entries may change on resume)"));
      const Metadata     meta = read_metadata(from);
      const unsigned int n    = state.n_transferable_fields();
      AssertThrow(meta.count("fields") &&
                    std::stoul(meta.at("fields")) ==
                      n + (meta.count("sprung") && meta.at("sprung") == "1"),
                  ExcMessage("--resume: the checkpoint in " + from +
                             " was written by a formsolve that stores "
                             "other fields; start the run again"));
      auto values = load_part(from, meta, state, "--resume");
      values.resize(n); // without the sprung shape
      state.set_transferable_fields(values);

      state.time = std::stod(meta.at("time"));
      state.step = std::stoul(meta.at("step"));
      for (unsigned int t = 0; t < state.tools.size(); ++t)
        {
          const auto key = "tool." + std::to_string(t);
          state.tools.restore(t,
                              tensor<dim>(meta.at(key + ".position")),
                              std::stod(meta.at(key + ".travel")),
                              tensor<dim>(meta.at(key + ".velocity")));
        }
      for (auto &f : state.force_controls)
        {
          const auto key = "control." + std::to_string(f.tool);
          f.active       = meta.at(key + ".active") == "1";
          f.velocity     = std::stod(meta.at(key + ".velocity"));
        }
      for (std::size_t b = 0; b < state.beads.size(); ++b)
        {
          const auto key       = "bead." + std::to_string(b);
          state.beads[b].work  = std::stod(meta.at(key + ".work"));
          state.beads[b].drawn = std::stod(meta.at(key + ".drawn"));
        }
      state.holder.released       = meta.at("holder.released") == "1";
      state.holder.release_travel = std::stod(meta.at("holder.release_travel"));
      state.update_contact_areas();
      return meta;
    }

#define INSTANTIATE(dim)                                          \
  template class Checkpoint<dim>;                                 \
  template std::vector<VectorType> load_part(const std::string &, \
                                             const Metadata &,    \
                                             State<dim> &,        \
                                             const std::string &, \
                                             std::vector<bool> *);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
