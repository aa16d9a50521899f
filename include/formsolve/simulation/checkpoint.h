// Checkpoint and restart: the State (distributed mesh, nodal fields with the
// contact state, quadrature history, tools, holder, time) and the time
// loop's own values, written atomically into <Output directory>/checkpoint.
#pragma once

#include <formsolve/state/state.h>

#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace simulation
  {
    using state::State;
    using state::VectorType;

    /// What the time loop needs besides the State, as text key = value.
    using Metadata = std::map<std::string, std::string>;

    /// @p x as text that reads back to the same double (17 digits).
    std::string exact_text(const double x);

    /// The newest complete checkpoint folder in @p directory, "" if none.
    std::string newest_checkpoint(const std::string &directory);
    /// The time loop's values of checkpoint folder @p from (meta.txt).
    Metadata read_metadata(const std::string &from);
    /// The parameter listing of the run that wrote checkpoint @p from.
    std::string read_parameters(const std::string &from);

    /// The mesh, history and nodal fields of checkpoint @p from (with its
    /// @p meta) into @p state, whose triangulation must be empty and whose
    /// Geometry and Mesh must be the writer's; returns the nodal fields as
    /// saved (State::transferable_fields() of the writer, then its sprung
    /// displacement if meta "sprung" is 1). A trimmed part's checkpoint
    /// (meta "trimmed" is 1) also holds which cells the part kept: into
    /// @p kept (by active cell index, locally owned cells) if given.
    /// Errors name @p who.
    template <int dim>
    std::vector<VectorType> load_part(const std::string &from,
                                      const Metadata    &meta,
                                      State<dim>        &state,
                                      const std::string &who,
                                      std::vector<bool> *kept = nullptr);

    template <int dim>
    class Checkpoint
    {
    public:
      /// @p parameters: the complete parameter listing of the run; a
      /// checkpoint is only resumed by the same case (Output entries aside).
      Checkpoint(const std::string &output_directory,
                 const std::string &parameters);

      /// Writes a complete checkpoint (collective) into checkpoint.new and
      /// renames it to checkpoint when every rank has finished, so that a
      /// process killed at any moment leaves the last complete one. With
      /// @p sprung (owned, on the state's DoFs), the sprung part's
      /// displacement is saved after the state's fields; with @p kept (a
      /// trimmed part's cells, by active cell index), which cells it kept.
      void save(const State<dim>        &state,
                const Metadata          &meta,
                const VectorType        *sprung = nullptr,
                const std::vector<bool> *kept   = nullptr) const;

      /// Loads the newest complete checkpoint into @p state, whose
      /// triangulation must be empty; returns the time loop's values.
      /// Throws naming --resume if there is none, or if it is another case's.
      Metadata load(State<dim> &state) const;

    private:
      std::string directory, parameters;
    };
  } // namespace simulation
} // namespace formsolve
