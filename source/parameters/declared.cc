#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace formsolve
{
  namespace parameters
  {
    std::string exact_text(const double x)
    {
      char text[32];
      for (int digits = 6; digits <= 17; ++digits)
        {
          std::snprintf(text, sizeof text, "%.*g", digits, x);
          if (std::strtod(text, nullptr) == x)
            break;
        }
      return text;
    }

    Declarations::Declarations(dealii::ParameterHandler &prm)
        : prm(prm)
    {}

    DeclaredSection &Declarations::here()
    {
      DeclaredSection *s = &root;
      for (const auto &p : path)
        s = &s->sections[p];
      return *s;
    }

    void Declarations::enter(const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      path.push_back(subsection);
      here(); // an empty subsection is listed too
    }

    void Declarations::leave()
    {
      prm.leave_subsection();
      path.pop_back();
    }

    void
    Declarations::declare(const std::string &name,
                          const std::string &default_text,
                          const Accepts     &accepts,
                          const std::string &documentation,
                          const std::function<void(const std::string &)> &read)
    {
      read(default_text);
      prm.declare_entry(name, default_text, *accepts.pattern, documentation);
      prm.add_action(name, read);
      here().entries[name] = {default_text, accepts, documentation};
    }

    void Declarations::add(const std::string &name,
                           double            &value,
                           const Accepts     &accepts,
                           const std::string &documentation)
    {
      declare(name,
              exact_text(value),
              accepts,
              documentation,
              [&value](const std::string &text) {
                value = std::strtod(text.c_str(), nullptr);
              });
    }

    void Declarations::add(const std::string &name,
                           unsigned int      &value,
                           const Accepts     &accepts,
                           const std::string &documentation)
    {
      declare(name,
              std::to_string(value),
              accepts,
              documentation,
              [&value](const std::string &text) {
                value = std::strtoul(text.c_str(), nullptr, 10);
              });
    }

    void Declarations::add(const std::string &name,
                           bool              &value,
                           const std::string &documentation)
    {
      declare(name,
              value ? "true" : "false",
              true_or_false(),
              documentation,
              [&value](const std::string &text) {
                value = text == "true" || text == "yes";
              });
    }

    void Declarations::add(const std::string &name,
                           std::string       &value,
                           const Accepts     &accepts,
                           const std::string &documentation)
    {
      declare(name,
              value,
              accepts,
              documentation,
              [&value](const std::string &text) { value = text; });
    }

    namespace
    {
      std::string joined(const double *x, const std::size_t n)
      {
        std::string t;
        for (std::size_t i = 0; i < n; ++i)
          t += (i ? ", " : "") + exact_text(x[i]);
        return t;
      }

      std::vector<double> numbers_in(const std::string &text)
      {
        return dealii::Utilities::string_to_double(
          dealii::Utilities::split_string_list(text, ','));
      }
    } // namespace

    namespace
    {
      void assign(std::vector<double> &values, const std::vector<double> &v)
      {
        values = v;
      }

      void assign(std::array<double, 3> &values, const std::vector<double> &v)
      {
        std::copy(v.begin(), v.end(), values.begin());
      }
    } // namespace

    template <typename Numbers>
    void Declarations::add_numbers(const std::string &name,
                                   Numbers           &values,
                                   const Accepts     &accepts,
                                   const std::string &documentation)
    {
      declare(name,
              joined(values.data(), values.size()),
              accepts,
              documentation,
              [&values](const std::string &text) {
                assign(values, numbers_in(text));
              });
    }

    void Declarations::add(const std::string   &name,
                           std::vector<double> &values,
                           const Accepts       &accepts,
                           const std::string   &documentation)
    {
      add_numbers(name, values, accepts, documentation);
    }

    void Declarations::add(const std::string     &name,
                           std::array<double, 3> &values,
                           const Accepts         &accepts,
                           const std::string     &documentation)
    {
      add_numbers(name, values, accepts, documentation);
    }
  } // namespace parameters
} // namespace formsolve
