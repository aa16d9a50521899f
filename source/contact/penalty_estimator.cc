#include <deal.II/base/exceptions.h>

#include <formsolve/contact/penalty_estimator.h>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    void FixedPenalty<dim>::estimate(const ContactSet<dim>     &set,
                                     const tools::ToolSet<dim> &tools,
                                     std::vector<double>       &epsilon)
    {
      epsilon.resize(set.pairs.size());
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        epsilon[k] =
          tools.penalty_factor(set.pairs[k].tool) * set.pairs[k].area;
    }

    template <int dim>
    std::unique_ptr<PenaltyEstimator<dim>>
    create_penalty_estimator(const parameters::Contact &p)
    {
      AssertThrow(p.penalty_strategy == "fixed",
                  dealii::ExcMessage("Contact/Penalty strategy: '" +
                                     p.penalty_strategy +
                                     "' is not available"));
      return std::make_unique<FixedPenalty<dim>>();
    }

    template class FixedPenalty<2>;
    template class FixedPenalty<3>;
    template std::unique_ptr<PenaltyEstimator<2>>
    create_penalty_estimator<2>(const parameters::Contact &);
    template std::unique_ptr<PenaltyEstimator<3>>
    create_penalty_estimator<3>(const parameters::Contact &);
  } // namespace contact
} // namespace formsolve
