// The forces of a round draw bead per unit length from its geometry, by
// bending and unbending the sheet over the bead and the groove's two
// shoulders with Coulomb friction on the arcs between (doc/theory.md,
// section 6d): a rigid-plastic sheet in plane strain, each bend or unbend
// adding M_p / rho to the line tension, each arc multiplying it by
// exp(mu theta).
#pragma once

namespace formsolve
{
  namespace beads
  {
    struct BeadGeometry
    {
      double bead_radius     = 4;   // mm
      double shoulder_radius = 4;   // mm
      double friction        = 0.1; // -
    };

    struct BeadForces
    {
      double restraining = 0; // N/mm, line tension the bead adds
      double opening     = 0; // N/mm, pushing die and holder apart
      double wrap_angle  = 0; // rad, over each shoulder (2x over the bead)
    };

    /// Angle the sheet's mid-surface turns through over each shoulder at
    /// penetration @p p (mm) of the bead into its groove, for a sheet of
    /// thickness @p t in the tightest groove (bead and shoulders both
    /// touching the sheet): 0 at p = 0, pi/2 at p = R_b + R_s + t.
    double wrap_angle(const BeadGeometry &g, const double p, const double t);

    /// The forces at penetration @p p (mm) for a sheet of thickness @p t
    /// (mm) and plane-strain flow stress @p sigma_ps (MPa).
    BeadForces bead_forces(const BeadGeometry &g,
                           const double        p,
                           const double        t,
                           const double        sigma_ps);

    /// The equivalent plastic strain the passage over the bead adds at
    /// full wrap (the mean over the thickness of the six bends, von
    /// Mises in plane strain), for the flow stress the model uses.
    double passage_strain(const BeadGeometry &g, const double t);
  } // namespace beads
} // namespace formsolve
