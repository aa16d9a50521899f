#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <formsolve/contact/contact_search.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>

#include <map>
#include <unordered_map>

namespace formsolve
{
  namespace contact
  {
    using namespace dealii;

    template <int dim>
    ContactSearch<dim>::ContactSearch(const double search_distance)
        : search_distance(search_distance)
    {}

    template <int dim>
    void ContactSearch<dim>::setup(const DoFHandler<dim> &dof_handler,
                                   const Mapping<dim>    &reference_mapping,
                                   ContactSet<dim>       &set) const
    {
      set.nodes.clear();
      set.pairs.clear();
      const auto &fe    = dof_handler.get_fe();
      const auto  owned = dof_handler.locally_owned_dofs();
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(reference_mapping,
                                           dof_handler,
                                           support);

      std::unordered_map<types::global_dof_index, unsigned int> seen;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == geometry::free_surface)
              {
                cell->face(f)->get_dof_indices(face_dofs);
                // Group the face DoFs by support point (base shape function).
                std::map<unsigned int, std::array<types::global_dof_index, dim>>
                  by_point;
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  {
                    const auto ci = fe.face_system_to_component_index(i);
                    by_point[ci.second][ci.first] = face_dofs[i];
                  }
                for (const auto &[base, dofs] : by_point)
                  if (owned.is_element(dofs[0]) && seen.count(dofs[0]) == 0)
                    {
                      seen[dofs[0]] = set.nodes.size();
                      ContactNode<dim> node;
                      node.dofs               = dofs;
                      node.reference_position = support[dofs[0]];
                      set.nodes.push_back(node);
                    }
              }
    }

    template <int dim>
    void
    ContactSearch<dim>::update_areas(const DoFHandler<dim>        &dof_handler,
                                     const Mapping<dim>           &mapping,
                                     const model::Kinematics<dim> &kinematics,
                                     ContactSet<dim>              &set) const
    {
      const auto           &fe = dof_handler.get_fe();
      VectorType            area(dof_handler.locally_owned_dofs(),
                      dof_handler.get_triangulation().get_communicator());
      const QGauss<dim - 1> quadrature(fe.degree + 1);
      FEFaceValues<dim>     fe_face(mapping,
                                fe,
                                quadrature,
                                update_values | update_JxW_values |
                                  update_normal_vectors |
                                  update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      Vector<double>                       local(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == geometry::free_surface)
              {
                fe_face.reinit(cell, f);
                local = 0;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    const double dA =
                      fe_face.JxW(q) *
                      kinematics.volume_factor(fe_face.quadrature_point(q));
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      {
                        const unsigned int c =
                          fe.system_to_component_index(i).first;
                        local[i] += fe_face.shape_value_component(i, q, c) *
                                    fe_face.normal_vector(q)[c] * dA;
                      }
                  }
                cell->get_dof_indices(dofs);
                area.add(dofs, local);
              }
      area.compress(VectorOperation::add);
      for (auto &node : set.nodes)
        for (unsigned int d = 0; d < dim; ++d)
          node.area_vector[d] = area[node.dofs[d]];
    }

    template <int dim>
    void ContactSearch<dim>::evaluate(
      const tools::ToolSet<dim>         &tools,
      const std::vector<Tensor<1, dim>> &tool_velocities,
      const VectorType                  &u,
      const VectorType                  &v,
      const double                       dt,
      const ContactState                &state,
      ContactSet<dim>                   &set) const
    {
      AssertDimension(tool_velocities.size(), tools.size());
      set.pairs.clear();
      for (unsigned int k = 0; k < set.nodes.size(); ++k)
        {
          const auto    &node = set.nodes[k];
          Point<dim>     x    = node.reference_position;
          Tensor<1, dim> vel;
          for (unsigned int d = 0; d < dim; ++d)
            {
              x[d] += u[node.dofs[d]];
              vel[d] = v[node.dofs[d]];
            }
          for (unsigned int t = 0; t < tools.size(); ++t)
            {
              ContactPair<dim> pair;
              pair.gap = tools[t].signed_distance_within(x,
                                                         search_distance,
                                                         pair.normal);
              if (pair.gap > search_distance)
                continue;
              pair.node              = k;
              pair.tool              = t;
              pair.relative_velocity = vel - tool_velocities[t];
              pair.predicted_gap =
                pair.gap + (pair.normal * pair.relative_velocity) * dt;
              pair.area  = std::max(0., -(pair.normal * node.area_vector));
              pair.shift = state.shift(k, t);
              // A node that just touches (predicted gap = shift, zero
              // force) is active: its stiffness enters the linearisation.
              // From rest (the first step) the sheet lies on the die and
              // under the holder at zero gap; without them it floats on the
              // punch alone and the first Newton step moves it rigidly.
              pair.active = pair.predicted_gap <= pair.shift && pair.area > 0;
              set.pairs.push_back(pair);
            }
        }
    }

#define INSTANTIATE(dim) template class ContactSearch<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace contact
} // namespace formsolve
