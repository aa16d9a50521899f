#include <deal.II/base/exceptions.h>

#include <formsolve/contact/penalty_strategy.h>
#include <formsolve/parameters/choices.h>

#include <map>

namespace formsolve
{
  namespace contact
  {
    namespace
    {
      struct Entry
      {
        StrategyFactory<2> factory2;
        StrategyFactory<3> factory3;
      };

      std::map<std::string, Entry> &registry()
      {
        static std::map<std::string, Entry> r;
        return r;
      }
    } // namespace

    bool register_penalty_strategy(const std::string        &name,
                                   const StrategyFactory<2> &factory2,
                                   const StrategyFactory<3> &factory3)
    {
      registry()[name] = Entry{factory2, factory3};
      return parameters::add_choice("Contact/Penalty strategy", name);
    }

    std::string penalty_strategy_names()
    {
      std::string names;
      for (const auto &[name, entry] : registry())
        names += (names.empty() ? "" : "|") + name;
      return names;
    }

    template <int dim>
    std::unique_ptr<PenaltyStrategy<dim>>
    create_penalty_strategy(const parameters::Contact &p)
    {
      const auto it = registry().find(p.penalty_strategy);
      AssertThrow(it != registry().end(),
                  dealii::ExcMessage("Parameter Contact/Penalty strategy: '" +
                                     p.penalty_strategy + "' is not one of " +
                                     penalty_strategy_names()));
      if constexpr (dim == 2)
        return it->second.factory2(p);
      else
        return it->second.factory3(p);
    }

    template std::unique_ptr<PenaltyStrategy<2>>
    create_penalty_strategy<2>(const parameters::Contact &);
    template std::unique_ptr<PenaltyStrategy<3>>
    create_penalty_strategy<3>(const parameters::Contact &);
  } // namespace contact
} // namespace formsolve
