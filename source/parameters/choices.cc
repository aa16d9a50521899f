#include <formsolve/parameters/choices.h>

#include <map>
#include <set>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      // Filled by static variables of other translation units: constructed
      // on first use, whatever the order of their initialisation.
      std::map<std::string, std::set<std::string>> &registry()
      {
        static std::map<std::string, std::set<std::string>> r;
        return r;
      }
    } // namespace

    bool add_choice(const std::string &entry, const std::string &name)
    {
      registry()[entry].insert(name);
      return true;
    }

    std::string choices(const std::string &entry)
    {
      std::string names;
      for (const auto &name : registry()[entry])
        names += (names.empty() ? "" : "|") + name;
      return names;
    }
  } // namespace parameters
} // namespace formsolve
