#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/model/cell_kinematics.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/state/sheet_integrals.h>

#include <limits>

namespace formsolve
{
  namespace state
  {
    using namespace dealii;

    namespace
    {
      template <int dim>
      double integrate(const State<dim>   &s,
                       const Mapping<dim> &mapping,
                       const HistoryField *field)
      {
        model::CellKinematics<dim> k(s.kinematics,
                                     mapping,
                                     s.dof_handler.get_fe(),
                                     s.history_rule);
        double                     sum = 0;
        for (const auto &cell : s.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              k.reinit(cell);
              for (unsigned int q = 0; q < k.n_points(); ++q)
                sum +=
                  (field ? s.history.get_data(cell)[q].get()->**field : 1.) *
                  k.dV(q);
            }
        return Utilities::MPI::sum(sum, s.comm);
      }
    } // namespace

    template <int dim>
    double volume(const State<dim> &s)
    {
      return integrate(s, *s.mapping, nullptr);
    }

    template <int dim>
    double integral(const State<dim>   &s,
                    const HistoryField  field,
                    const Mapping<dim> *mapping)
    {
      return integrate(s, mapping ? *mapping : *s.mapping, &field);
    }

    template <int dim>
    HistoryMaximum<dim> maximum(const State<dim> &s, const HistoryField field)
    {
      const MPI_Comm comm  = s.comm;
      double         local = -std::numeric_limits<double>::max();
      for (const auto &cell : s.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &h : s.history.get_data(cell))
            local = std::max(local, h.get()->*field);
      HistoryMaximum<dim> m;
      m.value = Utilities::MPI::max(local, comm);
      // Where: of the points with the largest value (up to round-off, which
      // differs between partitions), the first in the canonical order.
      FEValues<dim> fv(*s.mapping,
                       s.dof_handler.get_fe(),
                       s.history_rule,
                       update_quadrature_points);
      bool          found = false;
      Point<dim>    best;
      for (const auto &cell : s.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto h      = s.history.get_data(cell);
            bool       reinit = true;
            for (unsigned int q = 0; q < h.size(); ++q)
              if (model::ties(h[q].get()->*field, m.value))
                {
                  if (reinit)
                    fv.reinit(cell), reinit = false;
                  if (!found || model::precedes(fv.quadrature_point(q), best))
                    best = fv.quadrature_point(q), found = true;
                }
          }
      const auto candidates =
        Utilities::MPI::all_gather(comm, std::make_pair(found, best));
      found = false;
      for (const auto &[f, p] : candidates)
        if (f && (!found || model::precedes(p, m.location)))
          m.location = p, found = true;
      return m;
    }


#define INSTANTIATE(dim)                                       \
  template double              volume(const State<dim> &);     \
  template double              integral(const State<dim> &,    \
                                        const HistoryField,    \
                                        const Mapping<dim> *); \
  template HistoryMaximum<dim> maximum(const State<dim> &, const HistoryField);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
