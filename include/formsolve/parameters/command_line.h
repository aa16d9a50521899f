// The command-line front: input file, --set overrides, --print-parameters.
#pragma once

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/tools.h>

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    struct CommandLine
    {
      std::string input_file;
      /// "Subsection/Sub/Entry" -> value, applied after the file, in order.
      std::vector<std::pair<std::string, std::string>> overrides;
      bool                                             help             = false;
      bool                                             print_parameters = false;
      bool                                             parameter_manual = false;
      bool                                             validate         = false;
      bool                                             resume           = false;

      /// Throws dealii::ExcMessage naming the bad argument.
      static CommandLine parse(int argc, char **argv);
      static std::string usage();
    };

    /// Reads the input file into what @p declarations binds (the additional
    /// tools' subsections declared first, into @p tools), then applies the
    /// overrides. Errors name the file or the entry.
    void
    read_input(Declarations &declarations, Tools &tools, const CommandLine &cl);
  } // namespace parameters
} // namespace formsolve
