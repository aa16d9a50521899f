// The volumetric rate of the incompressibility penalty with the volume
// correction (doc/theory.md, eq. 5, 5a), for the body's residual and for the
// history update alike.
#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <formsolve/model/cell_kinematics.h>

#include <cmath>
#include <vector>

namespace formsolve
{
  namespace state
  {
    using dealii::SymmetricTensor;
    using model::CellKinematics;
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// tr(D) + ln(dV/dV0)/dt at the points of @p k (reinit'ed, with the
    /// reference mapping): the volumetric rate with the accumulated volume
    /// error corrected (doc/theory.md, eq. 5).
    template <int dim>
    void volumetric_rates(const CellKinematics<dim>          &k,
                          const VectorType                   &v,
                          const double                        dt,
                          const double                        offset,
                          std::vector<SymmetricTensor<2, 3>> &D,
                          std::vector<double>                &rates)
    {
      k.rates(v, D);
      rates.resize(k.n_points());
      for (unsigned int q = 0; q < k.n_points(); ++q)
        {
          rates[q] = trace(D[q]);
          if (dt > 0)
            rates[q] += (std::log(k.dV(q) / k.dV_reference(q)) - offset) / dt;
        }
    }

    /// Mean of ln(dV/dV0) over the points of @p k (reinitialised).
    template <int dim>
    double log_volume_ratio(const CellKinematics<dim> &k)
    {
      double sum = 0;
      for (unsigned int q = 0; q < k.n_points(); ++q)
        sum += std::log(k.dV(q) / k.dV_reference(q));
      return sum / k.n_points();
    }
  } // namespace state
} // namespace formsolve
