// Every .prm entry is declared once: its name, the member that holds its
// value (whose initial value is the default), what it accepts and what it
// means. From that one declaration follow deal.II's entry, the reading of
// the value into the member (an action of the ParameterHandler), and the
// tree of declarations that the manual, --print-parameters and the input
// check read.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <formsolve/parameters/accepts.h>
#include <formsolve/parameters/choice.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace parameters
  {
    struct DeclaredEntry
    {
      std::string default_value;
      Accepts     accepts;
      std::string documentation;
    };

    struct DeclaredSection
    {
      std::map<std::string, DeclaredSection> sections;
      std::map<std::string, DeclaredEntry>   entries;
    };

    /// Declares entries into a ParameterHandler and keeps their tree.
    /// The members an entry is bound to must outlive the reading.
    class Declarations
    {
    public:
      explicit Declarations(dealii::ParameterHandler &prm);

      void enter(const std::string &subsection);
      void leave();

      void add(const std::string &name,
               double            &value,
               const Accepts     &accepts,
               const std::string &documentation);
      void add(const std::string &name,
               unsigned int      &value,
               const Accepts     &accepts,
               const std::string &documentation);
      void add(const std::string &name,
               bool              &value,
               const std::string &documentation);
      void add(const std::string &name,
               std::string       &value,
               const Accepts     &accepts,
               const std::string &documentation);
      /// Comma-separated numbers.
      void add(const std::string   &name,
               std::vector<double> &values,
               const Accepts       &accepts,
               const std::string   &documentation);
      void add(const std::string     &name,
               std::array<double, 3> &values,
               const Accepts         &accepts,
               const std::string     &documentation);

      template <typename T>
      void add(const std::string &name,
               T                 &value,
               const Choice<T>   &names,
               const std::string &documentation)
      {
        declare(name,
                names.name(value),
                one_of(names.pattern()),
                documentation,
                [&value, names](const std::string &text) {
                  value = names.parse(text);
                });
      }

      /// An entry whose text @p read turns into values (a list, a table, a
      /// number or a word): @p read is applied to @p default_text at once,
      /// so that the members hold the default.
      void declare(const std::string &name,
                   const std::string &default_text,
                   const Accepts     &accepts,
                   const std::string &documentation,
                   const std::function<void(const std::string &)> &read);

      const DeclaredSection    &tree() const { return root; }
      dealii::ParameterHandler &handler() { return prm; }

    private:
      DeclaredSection &here();
      /// Comma-separated numbers into a vector or an array.
      template <typename Numbers>
      void add_numbers(const std::string &name,
                       Numbers           &values,
                       const Accepts     &accepts,
                       const std::string &documentation);

      dealii::ParameterHandler &prm;
      DeclaredSection           root;
      std::vector<std::string>  path;
    };

    /// A subsection entered for the lifetime of this object.
    class Subsection
    {
    public:
      Subsection(Declarations &d, const std::string &name)
          : d(d)
      {
        d.enter(name);
      }
      ~Subsection() { d.leave(); }

    private:
      Declarations &d;
    };

    /// @p x as the shortest text that reads back as the same double.
    std::string exact_text(const double x);
  } // namespace parameters
} // namespace formsolve
