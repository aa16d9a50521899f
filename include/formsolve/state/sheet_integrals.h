// Integrals and extremes over the sheet: its volume, the volume integral of a
// history value, its largest value and where it is. All through the model's
// kinematics (2 pi r dV in axisymmetry), at the material points.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>

#include <formsolve/state/state.h>

namespace formsolve
{
  namespace state
  {
    /// A quantity stored at the quadrature points.
    using HistoryField = double QuadraturePointHistory::*;

    /// The largest value of a history field and where it is (current
    /// configuration), on all ranks.
    template <int dim>
    struct HistoryMaximum
    {
      double             value = 0;
      dealii::Point<dim> location;
    };

    /// Volume of the sheet, current configuration (mm^3), all ranks.
    template <int dim>
    double volume(const State<dim> &s);

    /// Integral of @p field over the sheet in the configuration of
    /// @p mapping (the current one if null), all ranks.
    template <int dim>
    double integral(const State<dim>           &s,
                    const HistoryField          field,
                    const dealii::Mapping<dim> *mapping = nullptr);

    /// Largest value of @p field at any material point, and its position
    /// (the first in the canonical order among ties), all ranks.
    template <int dim>
    HistoryMaximum<dim> maximum(const State<dim> &s, const HistoryField field);
  } // namespace state
} // namespace formsolve
