// State stored at quadrature points, transferable by refinement.
#pragma once

#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace formsolve
{
  namespace state
  {
    struct QuadraturePointHistory
        : public dealii::TransferableQuadraturePointData
    {
      double strain      = 0; // equivalent plastic strain (-)
      double strain_rate = 0; // equivalent strain rate of the last step (1/s)
      double flow_stress = 0; // MPa
      double mean_stress = 0; // MPa
      double thickness_strain =
        0;              // log strain along the through-thickness direction
      double oyane = 0; // Oyane's damage integral I (-)
      double cockcroft_latham =
        0; // int max(sigma_1, 0) d eps_bar (MPa), not yet / C_crit
      // Cell constant: the part of ln(dV/dV0) that the volume correction
      // leaves alone (doc/theory.md, eq. 5a); 0 until an adaptation, which
      // sets it so that a new cell starts with the volume error of the cells
      // it came from.
      double volume_offset = 0;

      /// The names of the values, in the order of pack_values() (output).
      static std::vector<std::string> value_names()
      {
        return {"equivalent_strain",
                "equivalent_strain_rate",
                "flow_stress",
                "mean_stress",
                "thickness_strain",
                "oyane",
                "cockcroft_latham_integral",
                "volume_offset"};
      }

      unsigned int number_of_values() const override { return 8; }
      void         pack_values(std::vector<double> &v) const override
      {
        v = {strain,
             strain_rate,
             flow_stress,
             mean_stress,
             thickness_strain,
             oyane,
             cockcroft_latham,
             volume_offset};
      }
      void unpack_values(const std::vector<double> &v) override
      {
        strain           = v[0];
        strain_rate      = v[1];
        flow_stress      = v[2];
        mean_stress      = v[3];
        thickness_strain = v[4];
        oyane            = v[5];
        cockcroft_latham = v[6];
        volume_offset    = v[7];
      }
    };

    template <int dim>
    using HistoryStorage = dealii::CellDataStorage<
      typename dealii::Triangulation<dim>::cell_iterator,
      QuadraturePointHistory>;
  } // namespace state
} // namespace formsolve
