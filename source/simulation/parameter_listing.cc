#include <formsolve/simulation/parameter_listing.h>

#include <algorithm>
#include <sstream>

namespace formsolve
{
  namespace simulation
  {
    std::string without_output(const std::string &listing)
    {
      std::istringstream in(listing);
      std::ostringstream out;
      std::string        line;
      int                depth = 0, skip_from = -1;
      while (std::getline(in, line))
        {
          const auto first = line.find_first_not_of(" \t");
          const auto word =
            first == std::string::npos ? "" : line.substr(first);
          if (word.rfind("subsection", 0) == 0)
            {
              if (skip_from < 0 && word == "subsection Output")
                skip_from = depth;
              ++depth;
            }
          else if (word == "end")
            {
              --depth;
              if (depth == skip_from)
                {
                  skip_from = -1;
                  continue;
                }
            }
          if (skip_from < 0 && !word.empty() && word[0] != '#')
            out << word << '\n';
        }
      return out.str();
    }

    std::map<std::string, std::string> entries(const std::string &listing)
    {
      std::map<std::string, std::string> e;
      std::istringstream                 in(without_output(listing));
      std::vector<std::string>           path;
      auto                               trim = [](std::string &t) {
        t.erase(0, t.find_first_not_of(" \t"));
        t.erase(t.find_last_not_of(" \t") + 1);
      };
      for (std::string line; std::getline(in, line);)
        {
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(line.substr(11));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              const auto eq = line.find('=');
              if (eq == std::string::npos)
                continue;
              std::string name  = line.substr(4, eq - 4),
                          value = line.substr(eq + 1);
              value             = value.substr(0, value.find(" # default:"));
              trim(name);
              trim(value);
              std::string key;
              for (const auto &p : path)
                key += p + "/";
              e[key + name] = value;
            }
        }
      return e;
    }

    std::string differences(const std::string              &saved,
                            const std::string              &now,
                            const std::string              &earlier,
                            const std::vector<std::string> &prefixes,
                            const std::vector<std::string> &except)
    {
      auto wanted = [&](const std::string &key) {
        if (std::find(except.begin(), except.end(), key) != except.end())
          return false;
        return prefixes.empty() ||
               std::any_of(prefixes.begin(),
                           prefixes.end(),
                           [&](const auto &p) { return key.rfind(p, 0) == 0; });
      };
      const auto         a = entries(saved), b = entries(now);
      std::ostringstream s;
      unsigned int       n   = 0;
      auto               say = [&](const std::string &key,
                     const std::string &was,
                     const std::string &is) {
        if (n++ < 10)
          s << (n > 1 ? "; " : "") << key << " = " << was << " in " << earlier
            << ", " << is << " now";
      };
      // Changed values first, then entries only one listing has.
      for (const auto &[key, value] : a)
        if (const auto it = b.find(key);
            wanted(key) && it != b.end() && it->second != value)
          say(key, "'" + value + "'", "'" + it->second + "'");
      for (const auto &[key, value] : a)
        if (wanted(key) && !b.count(key))
          say(key, "'" + value + "'", "no such entry");
      for (const auto &[key, value] : b)
        if (wanted(key) && !a.count(key))
          say(key, "absent", "'" + value + "'");
      if (n > 10)
        s << "; and " << n - 10 << " more";
      return s.str();
    }
  } // namespace simulation
} // namespace formsolve
