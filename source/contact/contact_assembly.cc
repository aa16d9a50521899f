#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <formsolve/contact/contact_assembly.h>
#include <formsolve/contact/contact_law.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    void add_contact_terms(const ContactSet<dim>           &set,
                           const std::vector<double>       &epsilon,
                           const tools::ToolSet<dim>       &tools,
                           const double                     v0,
                           const double                     dt,
                           const bool                       newton,
                           const AffineConstraints<double> &constraints,
                           TrilinosWrappers::SparseMatrix  *matrix,
                           TrilinosWrappers::MPI::Vector   *residual)
    {
      FullMatrix<double>                   Kc(dim, dim);
      Vector<double>                       rc(dim);
      std::vector<types::global_dof_index> node_dofs(dim);
      for (unsigned int k = 0; k < set.pairs.size(); ++k)
        {
          const auto &pair = set.pairs[k];
          if (!pair.active)
            continue;
          const auto f =
            penalty_friction_force(pair,
                                   epsilon[k],
                                   tools.friction_coefficient(pair.tool),
                                   v0,
                                   dt,
                                   newton);
          for (unsigned int a = 0; a < dim; ++a)
            {
              node_dofs[a] = set.nodes[pair.node].dofs[a];
              rc[a]        = -f.force[a];
              for (unsigned int b = 0; b < dim; ++b)
                Kc(a, b) = f.stiffness[a][b];
            }
          // Rows and columns given apart: no entries on constrained
          // diagonals (deal.II would add |K_c(i,i)| there).
          if (matrix)
            constraints.distribute_local_to_global(Kc,
                                                   node_dofs,
                                                   node_dofs,
                                                   *matrix);
          if (residual)
            constraints.distribute_local_to_global(rc, node_dofs, *residual);
        }
      if (matrix)
        matrix->compress(VectorOperation::add);
      if (residual)
        residual->compress(VectorOperation::add);
    }

#define INSTANTIATE(dim)                                             \
  template void add_contact_terms(const ContactSet<dim> &,           \
                                  const std::vector<double> &,       \
                                  const tools::ToolSet<dim> &,       \
                                  double,                            \
                                  double,                            \
                                  bool,                              \
                                  const AffineConstraints<double> &, \
                                  TrilinosWrappers::SparseMatrix *,  \
                                  TrilinosWrappers::MPI::Vector *);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace contact
} // namespace formsolve
