#include <formsolve/parameters/declared.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <sstream>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      using DeclTree = boost::property_tree::ptree;

      /// "Double 0...MAX_DOUBLE (inclusive)" -> "real >= 0", and the like.
      std::string range(const std::string &p)
      {
        const auto  space = p.find(' ');
        std::string kind  = p.substr(0, space);
        if (kind == "Bool")
          return "`true` or `false`";
        if ((kind != "Double" && kind != "Integer") ||
            space == std::string::npos)
          return p;
        std::string rest = p.substr(space + 1);
        if (rest.rfind("range ", 0) == 0)
          rest = rest.substr(6);
        const auto dots = rest.find("...");
        const auto end  = rest.find(" (inclusive)");
        if (dots == std::string::npos || end == std::string::npos)
          return p;
        const std::string lo = rest.substr(0, dots),
                          hi = rest.substr(dots + 3, end - dots - 3);
        const bool open_lo   = lo == "-MAX_DOUBLE" || lo == "-2147483648",
                   open_hi   = hi == "MAX_DOUBLE" || hi == "2147483647";
        kind                 = kind == "Double" ? "real" : "integer";
        if (open_lo && open_hi)
          return kind;
        if (open_hi)
          return kind + " >= " + lo;
        if (open_lo)
          return kind + " <= " + hi;
        return kind + " in [" + lo + ", " + hi + "]";
      }

      /// "[Selection a|b ]" -> "a \| b"; "[Double 0...MAX_DOUBLE (inclusive)]"
      /// -> "Double 0...MAX_DOUBLE (inclusive)".
      std::string accepts_text(std::string p)
      {
        if (p.size() >= 2 && p.front() == '[' && p.back() == ']')
          p = p.substr(1, p.size() - 2);
        while (!p.empty() && p.back() == ' ')
          p.pop_back();
        if (p.rfind("FileName", 0) == 0)
          return "a file path (relative to the .prm file that names it)";
        if (p == "Anything")
          return "text, as the meaning says";
        const std::string multiple = "MultipleSelection ";
        if (p.rfind(multiple, 0) == 0)
          {
            std::string        out;
            std::istringstream in(p.substr(multiple.size()));
            for (std::string name; std::getline(in, name, '|');)
              out += (out.empty() ? "`" : ", `") + name + "`";
            return "a comma-separated list of " + out;
          }
        const std::string selection = "Selection ";
        if (p.rfind(selection, 0) == 0)
          {
            std::string        names = p.substr(selection.size()), out;
            std::istringstream in(names);
            for (std::string name; std::getline(in, name, '|');)
              out += (out.empty() ? "`" : ", `") + name + "`";
            return "one of " + out;
          }
        return range(p);
      }


      DeclaredSection section_of(const DeclTree &tree)
      {
        DeclaredSection s;
        for (const auto &[key, child] : tree)
          if (child.get_child_optional("value"))
            s.entries[demangle_name(key)] = {
              child.get<std::string>("default_value"),
              child.get<std::string>("pattern_description"),
              child.get<std::string>("documentation")};
          else
            s.sections[demangle_name(key)] = section_of(child);
        return s;
      }
    } // namespace

    std::string demangle_name(const std::string &s)
    {
      std::string d;
      for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '_' && i + 2 < s.size() &&
            std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2])))
          {
            d += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          d += s[i];
      return d;
    }

    DeclaredSection declared(const dealii::ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      DeclTree tree;
      boost::property_tree::read_json(json, tree);
      return section_of(tree);
    }

    std::string accepted_values(const std::string &pattern)
    {
      return accepts_text(pattern);
    }
  } // namespace parameters
} // namespace formsolve
