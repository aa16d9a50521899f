#include <formsolve/app/rank_zero.h>
#include <formsolve/model/dimensions.h>
#include <formsolve/tools/mesh_tool.h>
#include <formsolve/tools/polyline_tool.h>
#include <formsolve/tools/profile_tool.h>
#include <formsolve/tools/tool_set.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;
    using parameters::ToolShape;

    namespace
    {
      template <int dim>
      Planform<dim> planform_of(const parameters::Tool &t)
      {
        Planform<dim> p;
        if (t.shape == ToolShape::round)
          {
            p.kind   = Planform<dim>::Kind::circle;
            p.radius = 0.5 * t.diameter;
          }
        else if (t.shape == ToolShape::rounded_rectangle)
          {
            p.kind          = Planform<dim>::Kind::rounded_rectangle;
            p.half_length   = 0.5 * t.length;
            p.half_width    = 0.5 * t.width;
            p.corner_radius = t.corner_radius;
          }
        else
          p.kind = Planform<dim>::Kind::unbounded;
        return p;
      }

      /// A Shape = mesh tool: read, placed (Gap moves it away from the
      /// sheet on side @p side, as for the analytic tools) and oriented;
      /// what orienting changed goes to @p notes. Errors name the entry.
      std::unique_ptr<MeshTool> mesh_tool(const parameters::Tool   &t,
                                          const int                 side,
                                          const double              thickness,
                                          const Tensor<1, 3>       &v,
                                          std::vector<std::string> &notes)
      {
        const std::string entry = "Tools/" + t.name + "/Mesh file: ";
        try
          {
            Tensor<1, 3> shift;
            for (unsigned int c = 0; c < 3; ++c)
              shift[c] = t.mesh_offset[c];
            shift[2] += side * t.gap;
            // Rank 0 reads (and meshes) the file, every rank gets it.
            const auto [mesh, note] =
              app::on_rank_zero<std::pair<SurfaceMesh, std::string>>(
                MPI_COMM_WORLD,
                [&] {
                  std::string n;
                  auto m = load_tool_mesh(t.mesh_file, t.facet_size, shift, n);
                  return std::make_pair(std::move(m), n);
                });
            double size = 0;
            for (const auto &x : mesh.vertices)
              size = std::max(size, (x - mesh.vertices[0]).norm());
            AssertThrow(size > thickness,
                        ExcMessage(t.mesh_file + " spans " +
                                   std::to_string(size) +
                                   " mm, less than the sheet thickness; "
                                   "lengths are in mm (a file in metres "
                                   "needs scaling by 1000)"));
            // Where the tool bends the sheet (mesh refinement): curvature
            // radii up to 20 sheet thicknesses.
            auto tool = std::make_unique<MeshTool>(t.name,
                                                   mesh,
                                                   t.mesh_file,
                                                   t.feature_angle,
                                                   20 * thickness,
                                                   0.5 * thickness,
                                                   v);
            for (const auto &n : {note, tool->side_note()})
              if (!n.empty())
                notes.push_back("Tools/" + t.name + ": " + n);
            return tool;
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream what;
            e.print_info(what);
            std::string text = what.str();
            text.erase(0, text.find_first_not_of(" \n"));
            AssertThrow(false, ExcMessage(entry + text));
          }
        return nullptr;
      }

      /// A Shape = mesh tool of the axisymmetric model: its r-z profile,
      /// read, moved by Mesh offset's z and Gap, and oriented. Errors name
      /// the entry.
      std::unique_ptr<PolylineTool>
      polyline_tool(const parameters::Tool   &t,
                    const int                 side,
                    const double              thickness,
                    const Tensor<1, 2>       &v,
                    std::vector<std::string> &notes)
      {
        const std::string entry = "Tools/" + t.name + "/Mesh file: ";
        try
          {
            auto lines = app::on_rank_zero<ProfileLines>(MPI_COMM_WORLD, [&] {
              return read_profile(t.mesh_file, t.facet_size);
            });
            for (auto &x : lines.points)
              x[1] += t.mesh_offset[2] + side * t.gap;
            auto tool = std::make_unique<PolylineTool>(t.name,
                                                       lines,
                                                       t.mesh_file,
                                                       t.feature_angle,
                                                       20 * thickness,
                                                       0.5 * thickness,
                                                       v);
            if (!tool->orientation_note().empty())
              notes.push_back("Tools/" + t.name + ": " +
                              tool->orientation_note());
            return tool;
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream what;
            e.print_info(what);
            std::string text = what.str();
            text.erase(0, text.find_first_not_of(" \n"));
            AssertThrow(false, ExcMessage(entry + text));
          }
        return nullptr;
      }
    } // namespace

    template <int dim>
    ToolSet<dim>::ToolSet(const parameters::Tools   &p,
                          const parameters::Contact &c,
                          const double               thickness)
        : stroke(p.punch_stroke)
        , speed(p.punch_speed)
    {
      using parameters::ToolMotion;
      Tensor<1, dim> down;
      down[dim - 1] = -1;
      // The punch comes first: punch_index() relies on it.
      add(p.punch,
          -1,
          +1,
          {ToolMotion::prescribed, down, p.punch_speed, 0, {}},
          0,
          c,
          thickness);
      if (p.die.enabled)
        die = tools.size();
      add(p.die, +1, -1, {ToolMotion::fixed, down, 0, 0, {}}, 0, c, thickness);
      if (p.blank_holder.enabled)
        holder = tools.size();
      const bool held = p.holder_control == parameters::HolderControl::force;
      add(p.blank_holder,
          +1,
          +1,
          {held ? ToolMotion::force : ToolMotion::fixed,
           down,
           0,
           0,
           p.holder_force},
          0,
          c,
          thickness);
      additional = tools.size();
      for (const auto &t : p.additional)
        {
          Motion<dim> m{t.motion, {}, t.speed, t.stroke, t.force};
          // An axisymmetric model's z is its second coordinate.
          for (unsigned int d = 0; d < dim; ++d)
            m.direction[d] = t.direction[d + 3 - dim];
          if (m.direction.norm() > 0)
            m.direction /= m.direction.norm();
          add(t,
              t.solid_inside ? -1 : +1,
              t.above ? +1 : -1,
              m,
              t.refinement_level,
              c,
              thickness);
        }
    }

    template <int dim>
    void ToolSet<dim>::add(const parameters::Tool    &t,
                           const int                  sa,
                           const int                  sb,
                           const Motion<dim>         &m,
                           const unsigned int         level,
                           const parameters::Contact &c,
                           const double               thickness)
    {
      if (!t.enabled)
        return;
      // A prescribed tool starts moving; the others stand until their force
      // equation moves them.
      const Tensor<1, dim> v = m.kind == parameters::ToolMotion::prescribed
                                 ? m.speed * m.direction
                                 : Tensor<1, dim>();
      if (t.shape == ToolShape::mesh)
        {
          if constexpr (dim == 3)
            tools.push_back(mesh_tool(t, sb, thickness, v, orientation_notes));
          else
            tools.push_back(
              polyline_tool(t, sb, thickness, v, orientation_notes));
        }
      else
        tools.push_back(std::make_unique<ProfileTool<dim>>(t.name,
                                                           planform_of<dim>(t),
                                                           sa,
                                                           sb,
                                                           sb > 0
                                                             ? thickness + t.gap
                                                             : -t.gap,
                                                           t.profile_radius,
                                                           v));
      friction.push_back(t.friction_coefficient);
      sides.push_back(sb);
      to_part.push_back(t.gap_from == parameters::GapFrom::part
                          ? t.gap
                          : std::numeric_limits<double>::quiet_NaN());
      penalty.push_back(t.penalty_factor > 0 ? t.penalty_factor
                                             : c.penalty_factor);
      allowed.push_back(t.allowed_penetration > 0 ? t.allowed_penetration
                                                  : c.allowed_penetration);
      keys.push_back(parameters::tool_key(t.name));
      motions.push_back(m);
      levels.push_back(level);
    }

    template <int dim>
    std::vector<unsigned int> ToolSet<dim>::force_controlled() const
    {
      std::vector<unsigned int> held;
      for (unsigned int i = 0; i < tools.size(); ++i)
        if (motions[i].kind == parameters::ToolMotion::force)
          held.push_back(i);
      return held;
    }

    template <int dim>
    void ToolSet<dim>::set_speed_along(const unsigned int i, const double u)
    {
      tools[i]->set_velocity(u * motions[i].direction);
    }

    template <int dim>
    std::vector<Tensor<1, dim>> ToolSet<dim>::velocities() const
    {
      std::vector<Tensor<1, dim>> v;
      for (const auto &tool : tools)
        v.push_back(tool->velocity());
      return v;
    }

    template <int dim>
    double ToolSet<dim>::speed_along(const unsigned int i) const
    {
      return tools[i]->velocity() * motions[i].direction;
    }

    template <int dim>
    void ToolSet<dim>::begin_step(const double dt)
    {
      for (unsigned int i = 0; i < tools.size(); ++i)
        {
          const auto &m = motions[i];
          if (m.kind == parameters::ToolMotion::prescribed && m.stroke > 0)
            set_speed_along(
              i,
              std::min(m.speed,
                       std::max(0., m.stroke - tools[i]->travel()) / dt));
        }
    }

    template <int dim>
    void ToolSet<dim>::advance(const double dt)
    {
      for (auto &t : tools)
        t->advance(dt);
    }

    template <int dim>
    void ToolSet<dim>::restore(const unsigned int    i,
                               const Tensor<1, dim> &displacement,
                               const double          travel,
                               const Tensor<1, dim> &velocity)
    {
      tools[i]->restore(displacement, travel);
      tools[i]->set_velocity(velocity);
    }

#define INSTANTIATE(dim) template class ToolSet<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace tools
} // namespace formsolve
