#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/contact/contact_law.h>
#include <formsolve/forming/force_equations.h>
#include <formsolve/model/dimensions.h>

#include <algorithm>
#include <limits>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    void ForceEquations<dim>::reinit(const std::vector<unsigned int> &held,
                                     const IndexSet                  &owned,
                                     const MPI_Comm                   comm)
    {
      const unsigned int m = held.size();
      tools                = held;
      b.resize(m);
      c.resize(m);
      for (unsigned int j = 0; j < m; ++j)
        {
          b[j].reinit(owned, comm);
          c[j].reinit(owned, comm);
        }
      for (auto *x : {&e, &rho, &u, &du, &nearest_gap, &nearest_dn})
        x->assign(m, 0.);
      on.assign(m, false);
      has_contact.assign(m, false);
    }

    template <int dim>
    void ForceEquations<dim>::begin_solve(const std::vector<double> &velocity,
                                          const std::vector<bool>   &active)
    {
      Assert(velocity.size() == size() && active.size() == size(),
             ExcInternalError());
      u  = velocity;
      on = active;
      std::fill(du.begin(), du.end(), 0.);
    }

    template <int dim>
    bool ForceEquations<dim>::any_active() const
    {
      return std::find(on.begin(), on.end(), true) != on.end();
    }

    template <int dim>
    std::vector<double> ForceEquations<dim>::speeds_at(const double alpha) const
    {
      std::vector<double> speeds(size());
      for (unsigned int j = 0; j < size(); ++j)
        speeds[j] = u[j] + alpha * du[j];
      return speeds;
    }

    template <int dim>
    void ForceEquations<dim>::move_tools(const std::vector<double> &velocities,
                                         tools::ToolSet<dim>       &set) const
    {
      for (unsigned int j = 0; j < size(); ++j)
        if (on[j])
          set.set_speed_along(tools[j], velocities[j]);
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    ForceEquations<dim>::tool_velocities(const std::vector<double> &speeds,
                                         const tools::ToolSet<dim> &set) const
    {
      auto velocities = set.velocities();
      for (unsigned int j = 0; j < size(); ++j)
        if (on[j])
          velocities[tools[j]] = set.velocity_along(tools[j], speeds[j]);
      return velocities;
    }

    template <int dim>
    void
    ForceEquations<dim>::assemble(const contact::ContactSet<dim>  &set,
                                  const std::vector<double>       &epsilon,
                                  const tools::ToolSet<dim>       &tool_set,
                                  const double                     v0,
                                  const double                     dt,
                                  const bool                       newton,
                                  const AffineConstraints<double> &constraints,
                                  const std::vector<double>       &targets)
    {
      const unsigned int m = size();
      std::vector<int>   row(tool_set.size(), -1);
      for (unsigned int j = 0; j < m; ++j)
        if (on[j])
          row[tools[j]] = j;
      std::vector<double> force(m, 0.), e_local(m, 0.), dn(m, -1.);
      std::vector<double> gap(m, std::numeric_limits<double>::max());
      std::vector<int>    engaged(m, 0);
      Vector<double>      bk(dim), ck(dim);
      std::vector<types::global_dof_index> dofs(dim);
      // Not b[j] = c[j] = 0: assigning a Trilinos vector compares maps
      // with communication that not every rank entered (MPI_ERR_TRUNCATE
      // on 2 ranks).
      for (unsigned int j = 0; j < m; ++j)
        {
          b[j] = 0;
          c[j] = 0;
        }
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        {
          const auto &pair = set.pairs[k];
          const int   j    = row[pair.tool];
          if (j < 0)
            continue;
          const Tensor<1, dim> &d = tool_set.motion(pair.tool).direction;
          if (!pair.active)
            {
              // Only a node whose surface faces the tool along d can take
              // its load: the tool must close on it moving along d.
              if (pair.area > 0 && pair.normal * d > 0.5 &&
                  pair.predicted_gap - pair.shift < gap[j])
                {
                  gap[j] = pair.predicted_gap - pair.shift;
                  dn[j]  = pair.normal * d;
                }
              continue;
            }
          const auto f =
            contact::penalty_friction_force(pair,
                                            epsilon[k],
                                            tool_set.friction_coefficient(
                                              pair.tool),
                                            v0,
                                            dt,
                                            newton);
          force[j] += f.force * d;
          const Tensor<1, dim> sd = f.stiffness * d, ds = d * f.stiffness;
          e_local[j] += d * sd;
          engaged[j] = 1;
          for (unsigned int a = 0; a < dim; ++a)
            {
              dofs[a] = set.nodes[pair.node].dofs[a];
              bk[a]   = sd[a];
              ck[a]   = ds[a];
            }
          constraints.distribute_local_to_global(bk, dofs, b[j]);
          constraints.distribute_local_to_global(ck, dofs, c[j]);
        }
      for (unsigned int j = 0; j < m; ++j)
        {
          b[j].compress(VectorOperation::add);
          c[j].compress(VectorOperation::add);
        }
      if (m == 0)
        return;
      const MPI_Comm comm = b[0].get_mpi_communicator();
      Utilities::MPI::sum(force, comm, force);
      Utilities::MPI::sum(e_local, comm, e_local);
      for (unsigned int j = 0; j < m; ++j)
        {
          rho[j]         = targets[j] - force[j];
          e[j]           = e_local[j];
          has_contact[j] = Utilities::MPI::max(engaged[j], comm) != 0;
          // The nearest open pair, for hold_or_close().
          nearest_gap[j] = Utilities::MPI::min(gap[j], comm);
          nearest_dn[j] =
            Utilities::MPI::max(gap[j] == nearest_gap[j] ? dn[j] : -1., comm);
        }
    }

    template <int dim>
    void ForceEquations<dim>::correct(const std::vector<unsigned int> &bordered,
                                      const VectorType                &y,
                                      const std::vector<VectorType>   &z)
    {
      // Schur complement E - C^T K^-1 B: on its diagonal the stiffness a
      // tool meets, the penalty in series with the sheet under it. The
      // rigid-plastic Newton tangent has almost none along the current flow
      // (doc/theory.md, eq. 4), so it can vanish in round-off against e;
      // bounded below, du becomes a damped update there.
      const unsigned int n = bordered.size();
      FullMatrix<double> schur(n, n);
      Vector<double>     rhs(n), x(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int ji = bordered[i];
          rhs(i)                = rho[ji] + c[ji] * y;
          for (unsigned int k = 0; k < n; ++k)
            schur(i, k) = (i == k ? e[ji] : 0.) - c[ji] * z[k];
          schur(i, i) = std::max(schur(i, i), 1e-8 * e[ji]);
        }
      schur.gauss_jordan();
      schur.vmult(x, rhs);
      for (unsigned int i = 0; i < n; ++i)
        du[bordered[i]] = x(i);
    }

    template <int dim>
    void ForceEquations<dim>::hold_or_close(const unsigned int j,
                                            const double       depth,
                                            const double       dt)
    {
      du[j] = 0;
      if (!on[j] || has_contact[j] ||
          nearest_gap[j] == std::numeric_limits<double>::max())
        return;
      // The predicted gap changes by -(n . d) du dt. The candidates lie
      // within the search distance with n . d > 0.5, so the tool moves at
      // most twice that distance in the step.
      du[j] = (nearest_gap[j] + depth) / (nearest_dn[j] * dt);
    }

#define INSTANTIATE(dim) template class ForceEquations<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
