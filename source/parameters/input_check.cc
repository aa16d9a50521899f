#include <deal.II/base/exceptions.h>

#include <formsolve/parameters/input_check.h>

#include <algorithm>
#include <cctype>

namespace formsolve
{
  namespace parameters
  {
    using dealii::ExcMessage;

    namespace
    {
      std::string trim(const std::string &s)
      {
        const auto a = s.find_first_not_of(" \t\r");
        if (a == std::string::npos)
          return "";
        return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
      }

      std::string lower(std::string s)
      {
        for (auto &c : s)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
      }

      /// Levenshtein distance, case ignored.
      std::size_t distance(const std::string &x, const std::string &y)
      {
        const std::string        a = lower(x), b = lower(y);
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j)
          row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i)
          {
            std::size_t diagonal = row[0];
            row[0]               = i;
            for (std::size_t j = 1; j <= b.size(); ++j)
              {
                const std::size_t up = row[j];
                row[j]               = std::min({row[j] + 1,
                                                 row[j - 1] + 1,
                                                 diagonal + (a[i - 1] != b[j - 1])});
                diagonal             = up;
              }
          }
        return row[b.size()];
      }

      template <typename Map>
      std::vector<std::string> names_of(const Map &m)
      {
        std::vector<std::string> n;
        for (const auto &kv : m)
          n.push_back(kv.first);
        return n;
      }

      std::string join_path(const std::vector<std::string> &path)
      {
        std::string p;
        for (const auto &s : path)
          p += (p.empty() ? "" : "/") + s;
        return p;
      }

      /// "no subsection `X` in `A/B`; did you mean `Y`? (its subsections:
      /// ...)" or the same for an entry.
      std::string unknown(const std::string              &what,
                          const std::string              &name,
                          const std::vector<std::string> &path,
                          const std::vector<std::string> &names)
      {
        std::string m =
          "there is no " + what + " `" + name + "` " +
          (path.empty() ? std::string("at the top level")
                        : "in subsection `" + join_path(path) + "`");
        const std::string near = closest_names(name, names);
        if (!near.empty())
          m += "; did you mean " + near + "?";
        std::string list;
        for (const auto &n : names)
          list += (list.empty() ? "" : ", ") + n;
        m += " (declared " + (what == "entry" ? "entries" : what + "s") +
             " there: " + (list.empty() ? "none" : list) + ")";
        // A tool's subsection exists once the tool is listed.
        if (what == "subsection" && join_path(path) == "Tools")
          m += "; a tool besides Punch, Die and Blank holder must be named in "
               "Tools/Additional tools";
        return m;
      }

      /// The value's check against its entry's pattern, in plain words.
      void check_value(const DeclaredEntry &entry,
                       const std::string   &where,
                       const std::string   &value)
      {
        AssertThrow(entry.accepts.pattern->match(value),
                    ExcMessage(where + ": `" + value +
                               "` is not accepted; it takes " +
                               entry.accepts.words +
                               (value.find(',') != std::string::npos &&
                                    entry.accepts.takes_decimals
                                  ? " (write decimals with a point: 1.5)"
                                  : "")));
      }

      /// The section at @p path below @p root.
      const DeclaredSection *find(const DeclaredSection          &root,
                                  const std::vector<std::string> &path)
      {
        const DeclaredSection *s = &root;
        for (const auto &p : path)
          s = &s->sections.at(p);
        return s;
      }

      /// Enters subsection @p name of the section at @p path (pushed onto
      /// it), or throws "<where>: no subsection ...; did you mean ...".
      void enter(const DeclaredSection    &root,
                 std::vector<std::string> &path,
                 const std::string        &name,
                 const std::string        &where)
      {
        const DeclaredSection &here = *find(root, path);
        AssertThrow(
          here.sections.count(name),
          ExcMessage(
            where + ": " +
            unknown("subsection", name, path, names_of(here.sections))));
        path.push_back(name);
      }
    } // namespace

    std::pair<std::vector<std::string>, std::string>
    split_path(const std::string &path)
    {
      std::vector<std::string> parts;
      std::string::size_type   start = 0, slash;
      while ((slash = path.find('/', start)) != std::string::npos)
        {
          parts.push_back(path.substr(start, slash - start));
          start = slash + 1;
        }
      return {parts, path.substr(start)};
    }

    std::string closest_names(const std::string              &word,
                              const std::vector<std::string> &names)
    {
      std::size_t best = std::string::npos;
      for (const auto &n : names)
        best = std::min(best, distance(word, n));
      // A typo, not another word: at most a third of the letters changed.
      if (best == std::string::npos ||
          best > std::max<std::size_t>(2, word.size() / 3))
        return "";
      std::string out;
      for (const auto &n : names)
        if (distance(word, n) == best)
          out += (out.empty() ? "`" : " or `") + n + "`";
      return out;
    }

    void check_input(const DeclaredSection         &declared,
                     const std::vector<SourceLine> &physical)
    {
      // A line ending in a backslash goes on in the next one.
      std::vector<SourceLine> lines;
      bool                    continued = false;
      for (const auto &l : physical)
        {
          if (continued)
            lines.back().text += " " + l.text;
          else
            lines.push_back(l);
          std::string &t = lines.back().text;
          const auto   e = t.find_last_not_of(" \t\r");
          continued      = e != std::string::npos && t[e] == '\\';
          if (continued)
            t.erase(e);
        }
      std::vector<std::string> path;
      for (const auto &l : lines)
        {
          const std::string where = l.file + ", line " + std::to_string(l.line);
          std::string       text  = l.text.substr(0, l.text.find('#'));
          text                    = trim(text);
          if (text.empty())
            continue;
          const auto        space = text.find_first_of(" \t");
          const std::string word  = lower(text.substr(0, space));
          const std::string rest =
            space == std::string::npos ? "" : trim(text.substr(space));
          const DeclaredSection &here = *find(declared, path);
          if (word == "subsection")
            enter(declared, path, rest, where);
          else if (word == "end")
            {
              AssertThrow(!path.empty(),
                          ExcMessage(where +
                                     ": `end` without a subsection to close"));
              path.pop_back();
            }
          else if (word == "set")
            {
              const auto eq = rest.find('=');
              AssertThrow(eq != std::string::npos,
                          ExcMessage(where + ": `" + text +
                                     "` is not `set Entry = value`"));
              const std::string name = trim(rest.substr(0, eq));
              AssertThrow(
                here.entries.count(name),
                ExcMessage(
                  where + ": " +
                  unknown("entry", name, path, names_of(here.entries))));
              check_value(here.entries.at(name),
                          where + ": " + join_path(path) + "/" + name,
                          trim(rest.substr(eq + 1)));
            }
          else
            AssertThrow(false,
                        ExcMessage(where + ": `" + text +
                                   "` is neither `subsection Name`, `set "
                                   "Entry = value` nor `end`"));
        }
      AssertThrow(path.empty(),
                  ExcMessage(
                    (lines.empty() ? std::string("input") : lines.back().file) +
                    ": subsection `" + join_path(path) +
                    "` is not closed by `end`"));
    }

    void check_override(const DeclaredSection &declared,
                        const std::string     &path_text,
                        const std::string     &value)
    {
      const std::string where   = "--set \"" + path_text + "=" + value + "\"";
      const auto [parts, entry] = split_path(path_text);
      std::vector<std::string> path;
      for (const auto &p : parts)
        enter(declared, path, p, where);
      const DeclaredSection &here = *find(declared, path);
      AssertThrow(here.entries.count(entry),
                  ExcMessage(
                    where + ": " +
                    unknown("entry", entry, path, names_of(here.entries))));
      check_value(here.entries.at(entry), where, value);
    }
  } // namespace parameters
} // namespace formsolve
