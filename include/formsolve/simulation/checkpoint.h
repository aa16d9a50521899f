// Checkpoint and restart: the State (distributed mesh, nodal fields with the
// contact state, quadrature history, tools, holder, time) and the time
// loop's own values, written atomically into <Output directory>/checkpoint.
#pragma once

#include <formsolve/state/state.h>

#include <map>
#include <string>

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
      /// process killed at any moment leaves the last complete one.
      void save(const State<dim> &state, const Metadata &meta) const;

      /// Loads the newest complete checkpoint into @p state, whose
      /// triangulation must be empty; returns the time loop's values.
      /// Throws naming --resume if there is none, or if it is another case's.
      Metadata load(State<dim> &state) const;

    private:
      std::string directory, parameters;
    };
  } // namespace simulation
} // namespace formsolve
