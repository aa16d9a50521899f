#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <formsolve/contact/contact_law.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/solver/holder_equation.h>

#include <limits>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    void HolderEquation<dim>::reinit(const IndexSet &owned, const MPI_Comm comm)
    {
      b.reinit(owned, comm);
      c.reinit(owned, comm);
    }

    template <int dim>
    void HolderEquation<dim>::begin_solve(const double velocity)
    {
      w = w_trial = velocity;
      dw          = 0;
    }

    template <int dim>
    void
    HolderEquation<dim>::assemble(const contact::ContactSet<dim>  &set,
                                  const std::vector<double>       &epsilon,
                                  const tools::ToolSet<dim>       &tools,
                                  const double                     v0,
                                  const double                     dt,
                                  const bool                       newton,
                                  const AffineConstraints<double> &constraints,
                                  const double                     target)
    {
      const unsigned int                   holder = tools.holder_index();
      const unsigned int                   z      = dim - 1;
      Vector<double>                       bk(dim), ck(dim);
      std::vector<types::global_dof_index> dofs(dim);
      b              = 0;
      c              = 0;
      double force_z = 0, e_local = 0;
      int    active = 0;
      double gap = std::numeric_limits<double>::max(), nz = -1;
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        {
          const auto &pair = set.pairs[k];
          if (pair.tool != holder)
            continue;
          if (!pair.active)
            {
              // Only a node whose surface faces the holder from below can
              // take its load: the holder must close on it moving down.
              if (pair.area > 0 && pair.normal[z] < -0.5 &&
                  pair.predicted_gap - pair.shift < gap)
                {
                  gap = pair.predicted_gap - pair.shift;
                  nz  = pair.normal[z];
                }
              continue;
            }
          // The pair's force depends on v - w e_z: with S = -df/dv,
          // dr_k/dw = -S e_z, drho/dv_k = -e_z^T S, drho/dw = S_zz.
          const auto f =
            contact::penalty_friction_force(pair,
                                            epsilon[k],
                                            tools.friction_coefficient(holder),
                                            v0,
                                            dt,
                                            newton);
          force_z += f.force[z];
          e_local += f.stiffness[z][z];
          active = 1;
          for (unsigned int a = 0; a < dim; ++a)
            {
              dofs[a] = set.nodes[pair.node].dofs[a];
              bk[a]   = -f.stiffness[a][z];
              ck[a]   = -f.stiffness[z][a];
            }
          constraints.distribute_local_to_global(bk, dofs, b);
          constraints.distribute_local_to_global(ck, dofs, c);
        }
      b.compress(VectorOperation::add);
      c.compress(VectorOperation::add);
      const MPI_Comm comm = b.get_mpi_communicator();
      rho                 = target + Utilities::MPI::sum(force_z, comm);
      e                   = Utilities::MPI::sum(e_local, comm);
      has_contact         = Utilities::MPI::max(active, comm) != 0;
      // The nearest open pair, for closing_correction().
      const auto nearest = Utilities::MPI::min_max_avg(gap, comm);
      nearest_gap        = nearest.min;
      nearest_nz = Utilities::MPI::min(gap == nearest.min ? nz : 1., comm);
    }

    template <int dim>
    double HolderEquation<dim>::correction(const VectorType &y,
                                           const VectorType &z) const
    {
      // Schur complement e - c^T K^-1 b >= 0: the stiffness the holder
      // meets, the penalty in series with the sheet under it. The
      // rigid-plastic Newton tangent has almost none along the current flow
      // (doc/theory.md, eq. 4), so it can vanish in round-off against e;
      // bounded below, dw becomes a damped update there.
      const double schur = std::max(e - c * z, 1e-8 * e);
      return (-rho - c * y) / schur;
    }

    template <int dim>
    double HolderEquation<dim>::closing_correction(const double depth,
                                                   const double dt) const
    {
      if (nearest_gap == std::numeric_limits<double>::max())
        return 0;
      // The predicted gap changes by -n_z dw dt. The candidates lie within the
      // search distance with n_z < -0.5, so the holder moves at most twice
      // that distance in the step.
      return -(nearest_gap + depth) / (-nearest_nz * dt);
    }

#define INSTANTIATE(dim) template class HolderEquation<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
