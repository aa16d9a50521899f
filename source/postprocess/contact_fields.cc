#include <formsolve/model/dimensions.h>
#include <formsolve/postprocess/contact_fields.h>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    template <int dim>
    void ContactFields<dim>::fill(const state::State<dim>   &state,
                                  const std::vector<double> &epsilon,
                                  const double               search_distance)
    {
      // Accumulate per node first: mixing set and add on a Trilinos vector
      // triggers a collective exchange that ranks would reach unevenly.
      const auto         &set = state.contact_set;
      const unsigned int  n   = set.nodes.size();
      std::vector<double> gap(n, search_distance), pressure(n, 0.),
        penalty(n, 0.);
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        {
          const auto &p = set.pairs[k];
          gap[p.node]   = std::min(gap[p.node], p.predicted_gap);
          if (p.active)
            {
              pressure[p.node] += epsilon[k] * (p.shift - p.predicted_gap) /
                                  std::max(p.area, 1e-300);
              penalty[p.node] += epsilon[k];
            }
        }
      const std::vector<double> *values[3] = {&gap, &pressure, &penalty};
      for (unsigned int f = 0; f < 3; ++f)
        {
          VectorType owned(state.owned, state.comm);
          for (unsigned int j = 0; j < n; ++j)
            owned[set.nodes[j].dofs[0]] = (*values[f])[j];
          owned.compress(VectorOperation::insert);
          ghosted[f].reinit(state.owned, state.relevant, state.comm);
          ghosted[f] = owned;
        }
    }

    template <int dim>
    std::vector<NodalScalar> ContactFields<dim>::scalars() const
    {
      return {{"contact_gap", &ghosted[0], 0},
              {"contact_pressure", &ghosted[1], 0},
              {"penalty_factor", &ghosted[2], 0}};
    }

#define INSTANTIATE(dim) template class ContactFields<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
