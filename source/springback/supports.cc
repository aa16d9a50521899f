#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/parameters/require.h>
#include <formsolve/springback/supports.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace formsolve
{
  namespace springback
  {
    using namespace dealii;

    namespace
    {
      /// A DoF at its support point (current configuration).
      template <int dim>
      struct NodeDof
      {
        Point<dim>              x;
        types::global_dof_index index;
        unsigned int            component;
        bool                    owned;
      };

      /// The DoFs of the locally owned and ghost cells at their nodes.
      template <int dim>
      std::vector<NodeDof<dim>> node_dofs(const DoFHandler<dim> &dh,
                                          const Mapping<dim>    &mapping)
      {
        const auto &fe    = dh.get_fe();
        const auto &unit  = fe.get_unit_support_points();
        const auto  owned = dh.locally_owned_dofs();
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        std::vector<NodeDof<dim>>            out;
        for (const auto &cell : dh.active_cell_iterators())
          if ((cell->is_locally_owned() || cell->is_ghost()) &&
              cell->get_fe().n_dofs_per_cell() > 0) // not cut away
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                out.push_back(
                  {mapping.transform_unit_to_real_cell(cell, unit[i]),
                   dofs[i],
                   fe.system_to_component_index(i).first,
                   owned.is_element(dofs[i])});
            }
        return out;
      }

      /// The node with the smallest @p key over all ranks.
      template <int dim, typename Key>
      Point<dim> best_node(const std::vector<NodeDof<dim>> &nodes,
                           const Key                       &key,
                           const MPI_Comm                   comm)
      {
        double     best = std::numeric_limits<double>::max();
        Point<dim> x;
        for (const auto &n : nodes)
          if (key(n.x) < best)
            {
              best = key(n.x);
              x    = n.x;
            }
        const auto m = Utilities::MPI::min_max_avg(best, comm);
        return Utilities::MPI::broadcast(comm, x, m.min_index);
      }

      /// Component index of coordinate letter @p l in model @p m.
      unsigned int component_of(const char l, const model::Model m)
      {
        const auto names = model::coordinate_names(m);
        for (unsigned int c = 0; c < names.size(); ++c)
          if (names[c][0] == l)
            return c;
        AssertThrow(false, ExcMessage(std::string("no coordinate ") + l));
        return 0;
      }

      /// The rigid-body motions of the model at @p x, component @p c: the
      /// translation along z in axisymmetry; along x, z and the rotation
      /// about y in plane strain; translations and rotations (about the
      /// origin, per @p length) in 3-D.
      template <int dim>
      std::vector<double> modes(const model::Model m,
                                const Point<dim>  &x,
                                const unsigned int c,
                                const double       length)
      {
        if (m == model::Model::axisymmetric)
          return {c == 1 ? 1. : 0.};
        if constexpr (dim == 2)
          return {c == 0 ? 1. : 0.,
                  c == 1 ? 1. : 0.,
                  (c == 0 ? x[1] : -x[0]) / length};
        else
          {
            std::vector<double> v(6, 0.);
            v[c] = 1;
            for (unsigned int a = 0; a < 3; ++a)
              {
                // (e_a x x)_c
                Tensor<1, 3> e, r;
                e[a]     = 1;
                r        = cross_product_3d(e, Tensor<1, 3>(x));
                v[3 + a] = r[c] / length;
              }
            return v;
          }
      }

      std::vector<std::string> mode_names(const model::Model m,
                                          const unsigned int dim)
      {
        if (m == model::Model::axisymmetric)
          return {"translation along z"};
        if (dim == 2)
          return {"translation along x",
                  "translation along z",
                  "rotation about y"};
        return {"translation along x",
                "translation along y",
                "translation along z",
                "rotation about x",
                "rotation about y",
                "rotation about z"};
      }
    } // namespace

    template <int dim>
    std::vector<Support<dim>>
    choose_supports(const DoFHandler<dim>                       &dh,
                    const Mapping<dim>                          &mapping,
                    const model::Model                           m,
                    const std::vector<parameters::SupportPoint> &user)
    {
      const MPI_Comm            comm  = dh.get_communicator();
      const auto                nodes = node_dofs(dh, mapping);
      std::vector<Support<dim>> out;
      for (const auto &u : user)
        {
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = u.coordinates[d];
          out.push_back({best_node(
                           nodes,
                           [&](const Point<dim> &x) { return x.distance(p); },
                           comm),
                         u.components});
        }
      if (!user.empty())
        return out;
      // A: the node nearest to the z axis, the lowest of them; B: the
      // farthest along x, C: along y (3-2-1 for the full sheet).
      const auto lateral = [](const Point<dim> &x) {
        return dim == 2 ? std::abs(x[0]) : std::hypot(x[0], x[1]);
      };
      const double near = lateral(best_node(nodes, lateral, comm)) + 1e-9;
      const auto   a    = best_node(
        nodes,
        [&](const Point<dim> &x) {
          return lateral(x) <= near ? x[dim - 1]
                                         : std::numeric_limits<double>::max();
        },
        comm);
      const bool in_x = model::symmetric_in_x(m),
                 in_y = model::symmetric_in_y(m);
      if (dim == 2 || (in_x && in_y))
        return {{a, "z"}};
      const auto far_y = best_node(
        nodes,
        [](const Point<dim> &x) { return -x[1]; },
        comm);
      if (in_x)
        return {{a, "yz"}, {far_y, "z"}};
      const auto far_x = best_node(
        nodes,
        [](const Point<dim> &x) { return -x[0]; },
        comm);
      return {{a, "xyz"}, {far_x, "yz"}, {far_y, "z"}};
    }

    template <int dim>
    void add_supports(const DoFHandler<dim>           &dh,
                      const Mapping<dim>              &mapping,
                      const model::Model               m,
                      const std::vector<Support<dim>> &supports,
                      AffineConstraints<double>       &constraints)
    {
      const auto nodes = node_dofs(dh, mapping);
      for (const auto &s : supports)
        for (const char l : s.components)
          {
            const unsigned int c = component_of(l, m);
            for (const auto &n : nodes)
              if (n.component == c && n.x.distance(s.node) < 1e-9 &&
                  constraints.can_store_line(n.index) &&
                  !constraints.is_constrained(n.index))
                constraints.add_line(n.index);
          }
    }

    template <int dim>
    std::string free_rigid_motions(const DoFHandler<dim>           &dh,
                                   const Mapping<dim>              &mapping,
                                   const model::Model               m,
                                   const AffineConstraints<double> &c)
    {
      const MPI_Comm comm   = dh.get_communicator();
      const auto     nodes  = node_dofs(dh, mapping);
      double         length = 0;
      for (const auto &n : nodes)
        length = std::max(length, n.x.norm());
      length = std::max(Utilities::MPI::max(length, comm), 1e-300);
      const auto         names = mode_names(m, dim);
      const unsigned int k     = names.size();
      // The Gram matrix of the modes over the fixed DoFs (each once: the
      // owned ones): a motion r is free iff r^T G r = 0.
      std::vector<double>               gram(k * k, 0.);
      std::set<types::global_dof_index> counted;
      for (const auto &n : nodes)
        if (n.owned && c.is_constrained(n.index) &&
            c.get_constraint_entries(n.index)->empty() &&
            counted.insert(n.index).second)
          {
            const auto v = modes(m, n.x, n.component, length);
            for (unsigned int i = 0; i < k; ++i)
              for (unsigned int j = 0; j < k; ++j)
                gram[i * k + j] += v[i] * v[j];
          }
      Utilities::MPI::sum(gram, comm, gram);
      LAPACKFullMatrix<double> G(k, k);
      for (unsigned int i = 0; i < k; ++i)
        for (unsigned int j = 0; j < k; ++j)
          G(i, j) = gram[i * k + j];
      Vector<double>     values;
      FullMatrix<double> vectors;
      G.compute_eigenvalues_symmetric(-1., 1e300, 0., values, vectors);
      double largest = 0;
      for (const double v : values)
        largest = std::max(largest, v);
      std::string free;
      for (unsigned int e = 0; e < values.size(); ++e)
        if (values[e] <= 1e-10 * std::max(largest, 1.))
          {
            unsigned int dominant = 0;
            for (unsigned int i = 0; i < k; ++i)
              if (std::abs(vectors(i, e)) > std::abs(vectors(dominant, e)))
                dominant = i;
            free += (free.empty() ? "" : ", ") + names[dominant];
          }
      return free;
    }

    namespace
    {
      template <int dim>
      std::string describe(const std::vector<Support<dim>> &s,
                           const model::Model               m)
      {
        const auto         names = model::coordinate_names(m);
        std::ostringstream out;
        out.precision(4);
        for (unsigned int k = 0; k < s.size(); ++k)
          {
            out << (k ? "; " : "") << s[k].components << " at (";
            for (unsigned int d = 0; d < dim; ++d)
              out << (d ? ", " : "") << names[d] << " " << s[k].node[d];
            out << ")";
          }
        return out.str();
      }
    } // namespace

    namespace
    {
      template <int dim>
      std::vector<Support<dim>> slit_supports(const DoFHandler<dim> &dh,
                                              const Mapping<dim>    &mapping)
      {
        // The slit ring keeps the plane x = 0 for y < 0; left are the
        // translations along y and z and the rotation about x: y and z held
        // opposite the slit, z at the slit (none of them moves the slit
        // along x, so the opening does not depend on them).
        const auto     nodes = node_dofs(dh, mapping);
        const MPI_Comm comm  = dh.get_communicator();
        const auto     by_y  = [](const double sign) {
          return [sign](const Point<dim> &x) {
            return sign * x[1] - 1e-6 * x[dim - 1];
          };
        };
        return {{best_node(nodes, by_y(1), comm), "yz"},
                {best_node(nodes, by_y(-1), comm), "z"}};
      }

      template <int dim>
      void add_slit_symmetry(const state::State<dim>   &state,
                             const Mapping<dim>        &mapping,
                             const DoFHandler<dim>     &dh,
                             AffineConstraints<double> &constraints)
      {
        AffineConstraints<double> symmetry(constraints.get_local_lines());
        state::add_model_constraints(state.prm.geometry.model,
                                     state.reference_mapping,
                                     dh,
                                     symmetry);
        std::map<types::global_dof_index, double> y;
        for (const auto &n : node_dofs(dh, mapping))
          y[n.index] = n.x[dim == 3 ? 1 : 0];
        for (const auto &line : symmetry.get_lines())
          if (y.count(line.index) && y[line.index] <= 0 &&
              constraints.can_store_line(line.index) &&
              !constraints.is_constrained(line.index))
            constraints.add_line(line.index);
      }
    } // namespace

    template <int dim>
    std::string describe_supports(const std::vector<Support<dim>> &s,
                                  const model::Model               m)
    {
      return describe(s, m);
    }

    template <int dim>
    std::vector<Support<dim>> hold(const state::State<dim>   &state,
                                   const Mapping<dim>        &mapping,
                                   const DoFHandler<dim>     &dh,
                                   AffineConstraints<double> &constraints,
                                   const bool                 slit)
    {
      const auto m = state.prm.geometry.model;
      IndexSet   relevant;
      DoFTools::extract_locally_relevant_dofs(dh, relevant);
      constraints.clear();
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dh, constraints);
      if (slit)
        add_slit_symmetry(state, mapping, dh, constraints);
      else
        state::add_model_constraints(m,
                                     state.reference_mapping,
                                     dh,
                                     constraints);
      const auto supports =
        slit && state.prm.springback.supports.empty()
          ? slit_supports(dh, mapping)
          : choose_supports(dh, mapping, m, state.prm.springback.supports);
      add_supports(dh, mapping, m, supports, constraints);
      constraints.close();
      const std::string free = free_rigid_motions(dh, mapping, m, constraints);
      parameters::require(free.empty(),
                          "Springback/Supports",
                          "leave the part free to move (" + free +
                            ") with the symmetry planes of Geometry/Model = " +
                            model::name(m) +
                            "; held: " + describe(supports, m));
      return supports;
    }

    template <int dim>
    void check_supports(const state::State<dim> &state)
    {
      const unsigned int  d = state.prm.springback.degree;
      const FESystem<dim> fe(FE_Q<dim>(d > 0 ? d : state.fe.degree), dim);
      DoFHandler<dim>     dh(state.tria);
      dh.distribute_dofs(fe);
      AffineConstraints<double> constraints;
      hold(state, *state.mapping, dh, constraints, false);
    }

#define INSTANTIATE(dim)                                                                    \
  template std::vector<Support<dim>> choose_supports(                                       \
    const DoFHandler<dim> &,                                                                \
    const Mapping<dim> &,                                                                   \
    const model::Model,                                                                     \
    const std::vector<parameters::SupportPoint> &);                                         \
  template void                      add_supports(const DoFHandler<dim> &,                  \
                                                  const Mapping<dim> &,                     \
                                                  const model::Model,                       \
                                                  const std::vector<Support<dim>> &,        \
                                                  AffineConstraints<double> &);             \
  template std::string               free_rigid_motions(const DoFHandler<dim> &,            \
                                                        const Mapping<dim> &,               \
                                                        const model::Model,                 \
                                                        const AffineConstraints<double> &); \
  template std::vector<Support<dim>> hold(const state::State<dim> &,                        \
                                          const Mapping<dim> &,                             \
                                          const DoFHandler<dim> &,                          \
                                          AffineConstraints<double> &,                      \
                                          const bool);                                      \
  template void                      check_supports(const state::State<dim> &);             \
  template std::string describe_supports(const std::vector<Support<dim>> &,                 \
                                         const model::Model);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace springback
} // namespace formsolve
