// What the beads are and did, in words (the screen) and as key = value lines
// (run-summary.txt).
#include <formsolve/beads/bead_operator.h>
#include <formsolve/model/dimensions.h>

#include <cmath>
#include <sstream>

namespace formsolve
{
  namespace beads
  {
    template <int dim>
    BeadForces BeadOperator<dim>::full_forces(const unsigned int b) const
    {
      const auto &bead = params.beads[b];
      if (bead.model == parameters::BeadModel::forces)
        return {bead.restraining[0], bead.opening[0], 0.};
      return bead_forces({bead.bead_radius,
                          bead.shoulder_radius,
                          bead.friction},
                         bead.height,
                         t0,
                         sigma_ps[b]);
    }

    template <int dim>
    std::vector<std::string> BeadOperator<dim>::describe() const
    {
      std::vector<std::string> out;
      for (unsigned int b = 0; b < lines.size(); ++b)
        {
          const auto        &bead = params.beads[b];
          const auto         f    = full_forces(b);
          std::ostringstream s;
          s.precision(4);
          s << "draw bead `" << bead.name << "`: " << f.restraining
            << " N/mm restraining, " << f.opening << " N/mm opening";
          if (bead.model == parameters::BeadModel::geometry)
            s << " from its geometry (wrap " << f.wrap_angle * 180 / M_PI
              << " degrees over each shoulder, plane-strain flow stress "
              << sigma_ps[b] << " MPa, t0 " << t0 << " mm)";
          else if (bead.restraining.size() > 1 || bead.opening.size() > 1)
            s << " at the line's start, linear to its end";
          s << ", at full penetration (Height " << bead.height << " mm)";
          out.push_back(s.str());
        }
      return out;
    }

    template <int dim>
    std::string BeadOperator<dim>::summary_lines(
      const std::vector<state::BeadRecord> &records,
      const double                          symmetry) const
    {
      std::ostringstream s;
      for (unsigned int b = 0; b < lines.size(); ++b)
        {
          const std::string key    = "\n" + params.beads[b].key();
          const auto        f      = full_forces(b);
          double            length = 0;
          for (const auto &p : lines[b])
            length += p.weight;
          s << key << "_model = "
            << (params.beads[b].model == parameters::BeadModel::forces
                  ? "forces"
                  : "geometry")
            << key << "_length = " << symmetry * length << key
            << "_restraining_per_mm = " << f.restraining << key
            << "_opening_per_mm = " << f.opening;
          if (params.beads[b].model == parameters::BeadModel::geometry)
            s << key << "_wrap_angle = " << f.wrap_angle * 180 / M_PI << key
              << "_plane_strain_flow_stress = " << sigma_ps[b];
          s << key << "_work = " << symmetry * records[b].work << key
            << "_drawn = " << records[b].drawn;
        }
      return s.str();
    }

#define INSTANTIATE(dim)                                                  \
  template BeadForces BeadOperator<dim>::full_forces(unsigned int) const; \
  template std::vector<std::string> BeadOperator<dim>::describe() const;  \
  template std::string              BeadOperator<dim>::summary_lines(     \
    const std::vector<state::BeadRecord> &,                  \
    double) const;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace beads
} // namespace formsolve
