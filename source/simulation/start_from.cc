#include <formsolve/model/dimensions.h>
#include <formsolve/simulation/parameter_listing.h>
#include <formsolve/simulation/start_from.h>
#include <formsolve/state/sheet_integrals.h>
#include <formsolve/trimming/part_transfer.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    using namespace dealii;
    namespace fs = std::filesystem;

    namespace
    {
      const std::string entry = "Geometry/Start from";

      /// The value of @p key in @p meta, "" if absent.
      std::string value(const Metadata &meta, const std::string &key)
      {
        const auto it = meta.find(key);
        return it == meta.end() ? "" : it->second;
      }

      /// The earlier run's run-summary.txt as key -> value.
      std::map<std::string, std::string> summary(const std::string &folder)
      {
        std::map<std::string, std::string> s;
        std::ifstream                      in(folder + "/run-summary.txt");
        for (std::string line; std::getline(in, line);)
          if (const auto eq = line.find(" = "); eq != std::string::npos)
            s[line.substr(0, eq)] = line.substr(eq + 3);
        return s;
      }
    } // namespace

    EarlierRun find_earlier_run(const std::string &folder,
                                const std::string &output_directory,
                                const std::string &listing)
    {
      EarlierRun r;
      r.folder = folder;
      std::error_code ec;
      AssertThrow(fs::is_directory(folder, ec),
                  ExcMessage(entry + ": '" + folder + "' is not a folder"));
      // Not the folder read, nor a folder inside it.
      const auto read    = fs::weakly_canonical(folder, ec);
      const auto written = fs::weakly_canonical(output_directory, ec);
      const auto [end, _] =
        std::mismatch(read.begin(), read.end(), written.begin(), written.end());
      AssertThrow(end != read.end(),
                  ExcMessage(
                    "Output/Output directory: '" + output_directory +
                    (written == read ? "' is the folder "
                                     : "' lies in the folder ") +
                    entry +
                    " reads; a next operation never writes into it (choose "
                    "another Output directory)"));
      r.checkpoint = newest_checkpoint(folder);
      AssertThrow(!r.checkpoint.empty(),
                  ExcMessage(entry + ": '" + folder +
                             "' holds no finished formsolve run (no complete "
                             "checkpoint in it)"));
      const Metadata meta = read_metadata(r.checkpoint);
      AssertThrow(meta.count("finished"),
                  ExcMessage(entry + ": the run in '" + folder +
                             "' was made by a formsolve without next "
                             "operations, which did not mark its end; run "
                             "it again"));
      AssertThrow(value(meta, "finished") == "1",
                  ExcMessage(
                    entry + ": the run in '" + folder +
                    "' has not finished (its checkpoint is of step " +
                    value(meta, "step") +
                    ", during the run, or the run ended in a solver failure); "
                    "let it finish (--resume) first"));
      for (const auto *key : {"step", "punch_travel", "fields", "coarse_cells"})
        AssertThrow(!value(meta, key).empty(),
                    ExcMessage(entry + ": " + r.checkpoint +
                               "/meta.txt is incomplete (no '" + key +
                               "'); run the earlier case again"));
      const std::string diff = differences(read_parameters(r.checkpoint),
                                           listing,
                                           "the earlier run",
                                           {"Geometry/", "Mesh/", "Material/"},
                                           // The forming does not use
                                           // them: a springback may come
                                           // only with this run.
                                           {entry,
                                            "Material/Young's modulus",
                                            "Material/Poisson's ratio",
                                            "Material/Density"});
      AssertThrow(diff.empty(),
                  ExcMessage(entry + ": the part of '" + folder +
                             "' was formed with other Geometry, Mesh or "
                             "Material entries, which a next operation must "
                             "keep: " +
                             diff));
      r.steps      = std::stoul(value(meta, "step"));
      r.travel     = std::stod(value(meta, "punch_travel"));
      r.sprung     = value(meta, "sprung") == "1";
      r.trimmed    = value(meta, "trimmed") == "1";
      const auto s = summary(folder);
      if (r.trimmed)
        {
          r.earlier_volume = std::stod(value(s, "trimming_volume"));
          r.earlier_strain = std::stod(value(s, "trimming_strain_integral"));
        }
      r.end_reason = value(s, "end_reason");
      if (value(s, "trimming") == "failed")
        r.trim_failure = value(s, "trimming_failure");
      if (value(s, "split") == "yes")
        r.split = "at punch travel " + value(s, "split_travel") + " mm, at " +
                  value(s, "split_location") + " (" +
                  value(s, "split_measure") + ")";
      return r;
    }

    std::string summary_lines(const EarlierRun *earlier)
    {
      std::ostringstream s;
      s.precision(10);
      s << "\nstart_from = " << (earlier ? earlier->folder : "")
        << "\nstart_from_shape = "
        << (!earlier          ? ""
            : earlier->sprung ? "sprung"
                              : "as formed")
        << "\nstart_from_trimmed = "
        << (!earlier           ? ""
            : earlier->trimmed ? "yes"
                               : "no");
      if (!earlier)
        return s.str();
      s << "\nstart_from_volume = " << earlier->volume
        << "\nstart_from_earlier_volume = " << earlier->earlier_volume
        << "\nstart_from_strain_integral = " << earlier->strain
        << "\nstart_from_earlier_strain_integral = " << earlier->earlier_strain;
      if (earlier->trimmed)
        {
          const auto &m = earlier->part_mesh;
          s << "\nstart_from_mesh_level = " << m.level
            << "\nstart_from_coarse_cells = " << m.kept
            << "\nstart_from_coarse_cells_left_out = " << m.left_out
            << "\nstart_from_largest_move = " << m.largest_move
            << "\nstart_from_worst_corner_ratio = " << m.worst_corner_ratio;
        }
      return s.str();
    }

    template <int dim>
    void load_earlier_part(EarlierRun                      &earlier,
                           State<dim>                      &state,
                           const state::HistoryUpdate<dim> &update)
    {
      const Metadata meta = read_metadata(earlier.checkpoint);
      const auto     who  = entry + " = " + earlier.folder;
      if (!earlier.trimmed)
        {
          const auto fields = load_part(earlier.checkpoint, meta, state, who);
          state.set_shape(earlier.sprung ? fields.back() : fields[1]);
          state.update_contact_areas();
          earlier.volume = earlier.earlier_volume = state::volume(state);
          earlier.strain                          = earlier.earlier_strain =
            state::integral(state, &state::QuadraturePointHistory::strain);
          return;
        }
      // The earlier mesh with its cut-away cells, then the part alone.
      State<dim>        all(state.prm, state.comm);
      std::vector<bool> kept;
      const auto fields = load_part(earlier.checkpoint, meta, all, who, &kept);
      earlier.part_mesh = trimming::create_part_mesh(all, kept, state.tria);
      trimming::refine_like(all, earlier.part_mesh.level, state);
      trimming::transfer_part(all,
                              fields[1],
                              earlier.sprung ? fields.back() : fields[1],
                              update,
                              state);
      earlier.volume = state::volume(state);
      earlier.strain =
        state::integral(state, &state::QuadraturePointHistory::strain);
    }

#define INSTANTIATE(dim)                        \
  template void load_earlier_part(EarlierRun &, \
                                  State<dim> &, \
                                  const state::HistoryUpdate<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace simulation
} // namespace formsolve
