#include <formsolve/parameters/parameters.h>
#include <formsolve/parameters/require.h>

namespace formsolve
{
  namespace parameters
  {
    void Run::declare(ParameterHandler &prm)
    {
      Geometry::declare(prm);
      Mesh::declare(prm);
      MeshRefinement::declare(prm);
      Material::declare(prm);
      Tools::declare(prm);
      Contact::declare(prm);
      TimeStepping::declare(prm);
      NonlinearSolver::declare(prm);
      LinearSolver::declare(prm);
      Output::declare(prm);
    }

    void Run::parse(ParameterHandler &prm)
    {
      geometry.parse(prm);
      mesh.parse(prm);
      refinement.parse(prm);
      material.parse(prm);
      tools.parse(prm);
      contact.parse(prm);
      time.parse(prm);
      nonlinear.parse(prm);
      linear.parse(prm);
      output.parse(prm);
    }

    void Run::validate() const
    {
      geometry.validate();
      mesh.validate();
      refinement.validate(mesh.layers);
      material.validate();
      tools.validate();
      contact.validate();
      time.validate();
      nonlinear.validate();
      linear.validate();
      output.validate();

      const bool axi = geometry.model == model::Model::axisymmetric;
      for (const Tool *t : {&tools.punch, &tools.die, &tools.blank_holder})
        require(!axi || !t->enabled || t->shape != ToolShape::rounded_rectangle,
                "Tools/" + t->name + "/Shape",
                "must be round or flat for Geometry/Model = axisymmetric");
      if (tools.die.enabled && tools.die.shape == ToolShape::round &&
          geometry.blank_shape == BlankShape::round)
        require(
          geometry.blank_diameter > tools.die.diameter,
          "Geometry/Blank diameter",
          "must exceed Tools/Die/Diameter, or the blank falls through the die");
      require(!output.revolved_copy || axi,
              "Output/Revolved copy",
              "is only available for Geometry/Model = axisymmetric");
      require(time.end_of_run != EndOfRun::holder_release ||
                (tools.blank_holder.enabled &&
                 tools.blank_holder.shape != ToolShape::flat),
              "Time stepping/End of run",
              "'holder release' needs an enabled blank holder with an "
              "opening");
      require(time.end_of_run != EndOfRun::draw_through ||
                (tools.die.enabled && tools.die.shape != ToolShape::flat),
              "Time stepping/End of run",
              "'draw-through' needs an enabled die with an opening");
    }
  } // namespace parameters
} // namespace formsolve
