#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/contact/contact_search.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/state/state.h>

#include <limits>

namespace formsolve
{
  namespace state
  {
    using namespace dealii;

    template <int dim>
    State<dim>::State(const parameters::Run &run, const MPI_Comm comm)
        : prm(run)
        , comm(comm)
        , kinematics(run.geometry.model == model::Model::axisymmetric,
                     run.geometry.section_depth())
        , tria(comm)
        , fe(FE_Q<dim>(run.mesh.degree), dim)
        , dof_handler(tria)
        , history_rule(run.mesh.degree + 1)
        , reference_mapping(run.mesh.degree)
        , tools(run.tools, run.contact, run.geometry.thickness)
        , beads(run.tools.draw_beads.beads.size())
    {
      for (const unsigned int t : tools.force_controlled())
        force_controls.push_back({t});
      set_force_targets(0);
    }

    template <int dim>
    void State<dim>::create_mesh()
    {
      geometry::create_blank_mesh(prm.geometry, prm.mesh, tria);
      setup_dofs();
    }

    template <int dim>
    void add_model_constraints(const model::Model         m,
                               const Mapping<dim>        &reference,
                               const DoFHandler<dim>     &dof_handler,
                               AffineConstraints<double> &constraints)
    {
      // Nothing across a symmetry plane; nothing radial on the axis of an
      // axisymmetric model.
      const Functions::ZeroFunction<dim> zero(dim);
      const auto                        &fe = dof_handler.get_fe();
      auto fix = [&](const types::boundary_id id, const unsigned int c) {
        VectorTools::interpolate_boundary_values(
          reference,
          dof_handler,
          id,
          zero,
          constraints,
          fe.component_mask(FEValuesExtractors::Scalar(c)));
      };
      if (model::symmetric_in_x(m))
        fix(geometry::symmetry_x, 0);
      if (model::symmetric_in_y(m))
        fix(geometry::symmetry_y, 1);
      if (m == model::Model::axisymmetric)
        fix(geometry::axis, 0);
    }

    template <int dim>
    void State<dim>::setup_dofs()
    {
      mapping.reset();
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

      constraints.clear();
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      add_model_constraints(prm.geometry.model,
                            reference_mapping,
                            dof_handler,
                            constraints);
      constraints.close();

      velocity.reinit(owned, comm);
      displacement.reinit(owned, comm);
      velocity_ghost.reinit(owned, relevant, comm);
      displacement_ghost.reinit(owned, relevant, comm);
      mapping = std::make_unique<model::CurrentMapping<dim>>(prm.mesh.degree);
      update_mapping();
      history.clear();
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          history.initialize(cell, history_rule.size());
      contact::ContactSearch<dim>(prm.contact.search_distance)
        .setup(dof_handler, reference_mapping, contact_set);
      contact_state.reset(contact_set.nodes.size(), tools.size());
    }

    template <int dim>
    void State<dim>::update_mapping()
    {
      // The owned vector: MappingQCache makes its own ghosted copy (and
      // cannot import from a ghosted Trilinos vector).
      mapping->initialize(reference_mapping, dof_handler, displacement, true);
    }

    template <int dim>
    void State<dim>::update_contact_areas()
    {
      contact::ContactSearch<dim>(prm.contact.search_distance)
        .update_areas(dof_handler, *mapping, kinematics, contact_set);
    }

    template <int dim>
    void State<dim>::advance(const double                      dt,
                             const HistoryUpdate<dim>         &update,
                             const material::PointFrames<dim> *frames)
    {
      velocity_ghost = velocity;
      update
        .advance(dof_handler, *mapping, velocity_ghost, dt, history, frames);
      displacement.add(dt, velocity);
      displacement_ghost = displacement;
      update_mapping();
      tools.advance(dt);
      for (auto &b : beads)
        {
          b.work += b.power * dt;
          b.drawn += b.drawn_rate * dt;
        }
      time += dt;
      ++step;
    }

    template <int dim>
    StepSnapshot State<dim>::snapshot() const
    {
      return StepSnapshot{velocity, contact_state, control_velocities()};
    }

    template <int dim>
    void State<dim>::restore(const StepSnapshot &s)
    {
      velocity      = s.velocity;
      contact_state = s.contact_state;
      for (unsigned int j = 0; j < force_controls.size(); ++j)
        force_controls[j].velocity = s.control_velocities[j];
    }

    template <int dim>
    ForceControl *State<dim>::force_control(const unsigned int t)
    {
      for (auto &c : force_controls)
        if (c.tool == t)
          return &c;
      return nullptr;
    }

    template <int dim>
    const ForceControl *State<dim>::force_control(const unsigned int t) const
    {
      for (const auto &c : force_controls)
        if (c.tool == t)
          return &c;
      return nullptr;
    }

    template <int dim>
    void State<dim>::set_force_targets(const double punch_travel)
    {
      for (auto &c : force_controls)
        c.target = tools.motion(c.tool).force.at(punch_travel) /
                   prm.geometry.symmetry_factor();
    }

    template <int dim>
    std::vector<double> State<dim>::control_velocities() const
    {
      std::vector<double> u;
      for (const auto &c : force_controls)
        u.push_back(c.velocity);
      return u;
    }

    template <int dim>
    std::vector<bool> State<dim>::active_controls() const
    {
      std::vector<bool> on;
      for (const auto &c : force_controls)
        on.push_back(c.active);
      return on;
    }

    template <int dim>
    std::vector<VectorType> State<dim>::transferable_fields() const
    {
      std::vector<VectorType> fields = {velocity, displacement};
      for (auto &f : fields)
        {
          VectorType ghosted(owned, relevant, comm);
          ghosted = f;
          f.swap(ghosted);
        }
      // The records' persistent values per tool, at the node's first DoF.
      std::vector<VectorType> records(record_fields * tools.size(),
                                      VectorType(owned, comm));
      for (unsigned int k = 0; k < contact_set.nodes.size(); ++k)
        for (unsigned int t = 0; t < tools.size(); ++t)
          {
            const auto &r   = contact_state(k, t);
            const auto  dof = contact_set.nodes[k].dofs[0];
            auto       *f   = &records[record_fields * t];
            f[0][dof]       = r.factor;
            f[1][dof]       = r.scale;
            f[2][dof]       = r.shift;
            f[3][dof]       = r.active ? 1. : 0.;
          }
      for (auto &r : records)
        {
          r.compress(VectorOperation::insert);
          VectorType ghosted(owned, relevant, comm);
          ghosted = r;
          fields.push_back(ghosted);
        }
      return fields;
    }

    template <int dim>
    void
    State<dim>::set_transferable_fields(const std::vector<VectorType> &fields)
    {
      Assert(fields.size() == n_transferable_fields(), ExcInternalError());
      velocity     = fields[0];
      displacement = fields[1];
      constraints.distribute(velocity);
      constraints.distribute(displacement);
      velocity_ghost     = velocity;
      displacement_ghost = displacement;
      update_mapping();
      // Flips and locks belong to one solve and start again with the next.
      for (unsigned int k = 0; k < contact_set.nodes.size(); ++k)
        for (unsigned int t = 0; t < tools.size(); ++t)
          {
            auto       &r   = contact_state(k, t);
            const auto  dof = contact_set.nodes[k].dofs[0];
            const auto *f   = &fields[2 + record_fields * t];
            r.factor        = f[0][dof];
            // A node new to the surface takes its neighbours' mean: a scale
            // of at least 1, a multiplier of at least 0, the status of the
            // majority.
            r.scale  = std::max(1., double(f[1][dof]));
            r.shift  = std::max(0., double(f[2][dof]));
            r.active = f[3][dof] >= 0.5;
          }
    }

    template <int dim>
    void State<dim>::set_shape(const VectorType &shape)
    {
      velocity     = 0;
      displacement = shape;
      constraints.distribute(displacement);
      velocity_ghost     = velocity;
      displacement_ghost = displacement;
      update_mapping();
    }

    template <int dim>
    double State<dim>::max_lateral_distance(const unsigned int t) const
    {
      double d = -std::numeric_limits<double>::max();
      for (const auto &node : contact_set.nodes)
        {
          Point<dim> x = node.reference_position;
          for (unsigned int c = 0; c < dim; ++c)
            x[c] += displacement_ghost[node.dofs[c]];
          d = std::max(d, tools[t].lateral_distance(x));
        }
      return Utilities::MPI::max(d, comm);
    }

    template <int dim>
    double State<dim>::min_distance(const unsigned int t) const
    {
      double         d = std::numeric_limits<double>::max();
      Tensor<1, dim> normal;
      for (const auto &node : contact_set.nodes)
        {
          Point<dim> x = node.reference_position;
          for (unsigned int c = 0; c < dim; ++c)
            x[c] += displacement_ghost[node.dofs[c]];
          const double g = tools[t].signed_distance(x, normal);
          if (-(normal * node.area_vector) > 0) // the node's surface faces it
            d = std::min(d, g);
        }
      return Utilities::MPI::min(d, comm);
    }

#define INSTANTIATE(dim)                                       \
  template struct State<dim>;                                  \
  template void add_model_constraints(const model::Model,      \
                                      const Mapping<dim> &,    \
                                      const DoFHandler<dim> &, \
                                      AffineConstraints<double> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace state
} // namespace formsolve
