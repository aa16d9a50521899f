// What the user wrote, checked against the declarations before deal.II reads
// it, so that a mistake is reported in the user's words: the line and file,
// the misspelt subsection or entry with the closest declared names ("did you
// mean ..."), and for a value what the entry accepts.
#pragma once

#include <formsolve/parameters/declared.h>

#include <string>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    /// One line of the input with where it came from (includes expanded).
    struct SourceLine
    {
      std::string  file;
      unsigned int line = 0; // 1-based
      std::string  text;
    };

    /// Throws dealii::ExcMessage at the first unknown subsection or entry,
    /// unbalanced 'end', or value its entry does not accept.
    void check_input(const DeclaredSection         &declared,
                     const std::vector<SourceLine> &lines);

    /// The same for one --set "Sub/Sub/Entry=value".
    void check_override(const DeclaredSection &declared,
                        const std::string     &path,
                        const std::string     &value);

    /// "Sub/Sub/Entry" -> ({"Sub", "Sub"}, "Entry").
    std::pair<std::vector<std::string>, std::string>
    split_path(const std::string &path);

    /// The declared names closest to @p word (edit distance, ignoring
    /// case), as "`a`" or "`a` or `b`"; empty if none is close.
    std::string closest_names(const std::string              &word,
                              const std::vector<std::string> &names);
  } // namespace parameters
} // namespace formsolve
