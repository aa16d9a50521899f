#include <deal.II/base/exceptions.h>

#include <formsolve/parameters/command_line.h>
#include <formsolve/parameters/input_check.h>
#include <formsolve/parameters/tools.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    using dealii::ExcMessage;

    std::string CommandLine::usage()
    {
      return "Usage: formsolve [options] case.prm\n"
             "       mpirun -np N formsolve [options] case.prm\n\n"
             "Options:\n"
             "  --help                       this text\n"
             "  --print-parameters           write the complete, documented "
             "default\n"
             "                               parameter file to standard "
             "output\n"
             "  --parameter-manual           write the parameter manual "
             "(Markdown,\n"
             "                               doc/parameters.md) to standard "
             "output\n"
             "  --validate                   check the input (parameters, "
             "mesh, initial\n"
             "                               position of the tools) and stop; "
             "writes nothing\n"
             "  --resume                     continue from the checkpoint in "
             "the "
             "output folder\n"
             "                               (Output/Checkpoint interval)\n"
             "  --set \"Subsection/Entry=value\"\n"
             "                               override one entry after reading "
             "the file\n"
             "                               (repeatable; nested: "
             "Tools/Punch/Stroke=20)\n";
    }

    CommandLine CommandLine::parse(int argc, char **argv)
    {
      CommandLine cl;
      for (int i = 1; i < argc; ++i)
        {
          const std::string a = argv[i];
          if (a == "--help" || a == "-h")
            cl.help = true;
          else if (a == "--print-parameters")
            cl.print_parameters = true;
          else if (a == "--parameter-manual")
            cl.parameter_manual = true;
          else if (a == "--validate")
            cl.validate = true;
          else if (a == "--resume")
            cl.resume = true;
          else if (a == "--set" || a.rfind("--set=", 0) == 0)
            {
              std::string s;
              if (a == "--set")
                {
                  AssertThrow(
                    i + 1 < argc,
                    ExcMessage(
                      "--set needs an argument \"Subsection/Entry=value\""));
                  s = argv[++i];
                }
              else
                s = a.substr(6);
              const auto eq = s.find('=');
              AssertThrow(eq != std::string::npos && eq > 0,
                          ExcMessage(
                            "--set \"" + s +
                            "\": expected \"Subsection/Entry=value\""));
              cl.overrides.emplace_back(s.substr(0, eq), s.substr(eq + 1));
            }
          else if (a.size() > 1 && a[0] == '-')
            {
              AssertThrow(false, ExcMessage("unknown option " + a));
            }
          else
            {
              AssertThrow(cl.input_file.empty(),
                          ExcMessage("more than one input file given: " +
                                     cl.input_file + " and " + a));
              cl.input_file = a;
            }
        }
      return cl;
    }

    namespace
    {
      /// @p line with its value made absolute against @p folder if it sets
      /// one of the entries named @p paths to a relative path.
      std::string resolve_path(const std::string           &line,
                               const std::set<std::string> &paths,
                               const std::filesystem::path &folder)
      {
        const auto first = line.find_first_not_of(" \t");
        const auto equal = line.find('=');
        if (first == std::string::npos || equal == std::string::npos ||
            (line.compare(first, 4, "set ") != 0 &&
             line.compare(first, 4, "SET ") != 0))
          return line;
        auto trim = [](std::string t) {
          t.erase(0, t.find_first_not_of(" \t"));
          t.erase(t.find_last_not_of(" \t\r") + 1);
          return t;
        };
        const std::string name =
          trim(line.substr(first + 4, equal - first - 4));
        std::string value = line.substr(equal + 1), comment;
        if (const auto hash = value.find('#'); hash != std::string::npos)
          comment = value.substr(hash), value = value.substr(0, hash);
        value = trim(value);
        if (!paths.count(name) || value.empty() ||
            std::filesystem::path(value).is_absolute())
          return line;
        const auto full = (folder / value).lexically_normal();
        return line.substr(0, equal + 1) + " " + full.string() +
               (comment.empty() ? "" : " " + comment);
      }

      /// The lines of @p file with its 'include' lines replaced by the
      /// included files' lines (resolved against the including file), each
      /// with its origin; the entries named @p paths resolved alike.
      void expand_includes(const std::filesystem::path &file,
                           const unsigned int           depth,
                           const std::set<std::string> &paths,
                           std::vector<SourceLine>     &lines)
      {
        std::ifstream in(file);
        AssertThrow(in.good(),
                    ExcMessage("cannot open included file " + file.string()));
        AssertThrow(depth < 16,
                    ExcMessage("include nesting deeper than 16 at " +
                               file.string()));
        std::string  line;
        unsigned int number = 0;
        while (std::getline(in, line))
          {
            ++number;
            const auto first = line.find_first_not_of(" \t");
            if (first != std::string::npos &&
                (line.compare(first, 8, "include ") == 0 ||
                 line.compare(first, 8, "INCLUDE ") == 0))
              {
                std::string name = line.substr(first + 8);
                name.erase(0, name.find_first_not_of(" \t"));
                name.erase(name.find_last_not_of(" \t\r") + 1);
                std::filesystem::path inc(name);
                if (inc.is_relative())
                  inc = file.parent_path() / inc;
                expand_includes(inc, depth + 1, paths, lines);
              }
            else
              lines.push_back({file.filename().string(),
                               number,
                               resolve_path(line, paths, file.parent_path())});
          }
      }
    } // namespace

    namespace
    {
      /// The names of the entries that take an input file.
      void input_file_entries(const DeclaredSection &s,
                              std::set<std::string> &names)
      {
        for (const auto &[name, entry] : s.entries)
          if (entry.accepts.names_input_file)
            names.insert(name);
        for (const auto &[name, section] : s.sections)
          input_file_entries(section, names);
      }
    } // namespace

    void
    read_input(Declarations &declarations, Tools &tools, const CommandLine &cl)
    {
      dealii::ParameterHandler &prm = declarations.handler();
      {
        std::ifstream in(cl.input_file);
        AssertThrow(in.good(),
                    ExcMessage("cannot open input file " + cl.input_file));
      }
      // 'include' lines are resolved relative to the file that contains
      // them, at any depth (deal.II resolves them against the working
      // directory): expand them here, and the input files an entry names
      // (pattern FileName) alike. The output directory and --set values
      // stay relative to the working directory.
      std::set<std::string> paths;
      input_file_entries(declarations.tree(), paths);
      std::vector<SourceLine> lines;
      expand_includes(std::filesystem::absolute(cl.input_file),
                      0,
                      paths,
                      lines);
      std::string text;
      for (const auto &l : lines)
        text += l.text + '\n';
      // The additional tools' subsections exist once their names are known.
      tools.declare_additional(declarations,
                               additional_tool_names(text, cl.overrides));
      tools.draw_beads.declare_beads(declarations,
                                     draw_bead_names(text, cl.overrides));
      const DeclaredSection &tree = declarations.tree();
      check_input(tree, lines);
      try
        {
          prm.parse_input_from_string(text,
                                      cl.input_file,
                                      /*skip_undefined=*/false);
        }
      catch (const dealii::StandardExceptions::ExcMessage &)
        {
          throw; // an entry's own reading, which names it
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream s;
          e.print_info(s);
          AssertThrow(false,
                      ExcMessage("in input file " + cl.input_file + ": " +
                                 s.str()));
        }

      for (const auto &[path, value] : cl.overrides)
        {
          const auto [parts, entry] = split_path(path);
          check_override(tree, path, value);
          try
            {
              for (const auto &p : parts)
                prm.enter_subsection(p);
              prm.set(entry, value);
              for (unsigned int k = 0; k < parts.size(); ++k)
                prm.leave_subsection();
            }
          catch (const dealii::StandardExceptions::ExcMessage &)
            {
              throw; // an entry's own reading, which names it
            }
          catch (const dealii::ExceptionBase &e)
            {
              std::ostringstream s;
              e.print_info(s);
              AssertThrow(false,
                          ExcMessage("--set " + path + "=" + value + ": " +
                                     s.str()));
            }
        }
    }
  } // namespace parameters
} // namespace formsolve
