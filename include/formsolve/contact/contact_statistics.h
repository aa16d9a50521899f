// Per-tool forces and penetration statistics of a contact set (all ranks).
#pragma once

#include <deal.II/base/mpi.h>

#include <formsolve/contact/contact_set.h>
#include <formsolve/tools/tool_set.h>

#include <algorithm>
#include <vector>

namespace formsolve
{
  namespace contact
  {
    template <int dim>
    struct ContactStatistics
    {
      /// Force of the sheet on each tool (N), modelled part.
      std::vector<Tensor<1, dim>> tool_force;
      /// Normal force on each tool's side walls (pairs whose normal is
      /// within 6 degrees of horizontal, |n_z| < 0.1), N, modelled part.
      std::vector<double> tool_wall_force;
      /// Contact area of those pairs (mm^2, modelled part).
      std::vector<double> tool_wall_area;
      /// Punch travel (mm) of the configuration the forces act on: the
      /// start of the step, on which the velocities were solved.
      double              force_travel = 0;
      std::vector<double> tool_max_penetration; // mm, per tool, >= 0
      double              max_penetration  = 0; // mm, >= 0
      double              mean_penetration = 0; // mm, active pairs
      unsigned int        n_active         = 0;
      unsigned int        n_over_allowed = 0; // active pairs deeper than delta
      unsigned int        n_locked       = 0; // pairs whose status was locked
      double              min_factor     = 0; // N/mm, over active pairs
      double              max_factor     = 0;
    };

    /// Forces from the contact law with factors @p epsilon (one per pair)
    /// and friction regularisation @p v0, and penetration statistics of the
    /// predicted (end-of-step) gaps.
    /// The force squeezing the sheet wall between punch and die (N,
    /// modelled part): the smaller of the two tools' wall forces, 0 unless
    /// both press on the wall, i.e. the wall is ironed.
    template <int dim>
    double ironing_force(const ContactStatistics<dim> &s,
                         const unsigned int            punch,
                         const unsigned int            die)
    {
      return die < s.tool_wall_force.size()
               ? std::min(s.tool_wall_force[punch], s.tool_wall_force[die])
               : 0.;
    }

    /// The mean normal pressure on the ironed wall (MPa): the smaller of
    /// the punch's and the die's wall force per wall contact area, 0 unless
    /// both press on the wall.
    template <int dim>
    double ironing_pressure(const ContactStatistics<dim> &s,
                            const unsigned int            punch,
                            const unsigned int            die)
    {
      if (die >= s.tool_wall_area.size() || s.tool_wall_area[punch] <= 0 ||
          s.tool_wall_area[die] <= 0)
        return 0.;
      return std::min(s.tool_wall_force[punch] / s.tool_wall_area[punch],
                      s.tool_wall_force[die] / s.tool_wall_area[die]);
    }

    template <int dim>
    ContactStatistics<dim> statistics(const tools::ToolSet<dim> &tools,
                                      const ContactSet<dim>     &set,
                                      const std::vector<double> &epsilon,
                                      const double               v0,
                                      const double               dt,
                                      const MPI_Comm             comm);
  } // namespace contact
} // namespace formsolve
