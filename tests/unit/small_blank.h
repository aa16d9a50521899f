// A small test blank: 20 mm across, 1 mm thick, round for the axisymmetric
// model, square otherwise, the default tools; its State meshed with the
// default material's assembler.
#pragma once

#include <deal.II/base/mpi.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/parameters/parameters.h>
#include <formsolve/state/state.h>

namespace test
{
  inline formsolve::parameters::Run
  small_blank(const formsolve::model::Model      m,
              const formsolve::parameters::Mesh &mesh)
  {
    using namespace formsolve;
    parameters::Run prm;
    prm.geometry.model          = m;
    prm.geometry.blank_shape    = m == model::Model::axisymmetric
                                    ? parameters::BlankShape::round
                                    : parameters::BlankShape::rectangle;
    prm.geometry.blank_diameter = 20;
    prm.geometry.blank_length   = 20;
    prm.geometry.blank_width    = 20;
    prm.geometry.thickness      = 1;
    prm.mesh                    = mesh;
    return prm;
  }

  /// The parameters of small_blank(), their material, a meshed State and
  /// its assembler (members in construction order).
  template <int dim>
  struct SmallBlank
  {
    SmallBlank(const formsolve::model::Model      m,
               const formsolve::parameters::Mesh &mesh)
        : prm(small_blank(m, mesh))
        , material(prm.material)
        , state(prm, MPI_COMM_WORLD)
        , assembler(material, state.kinematics, state.reference_mapping, 1)
        , update(material, state.kinematics, state.reference_mapping, 1)
    {
      state.create_mesh();
    }

    const formsolve::parameters::Run             prm;
    const formsolve::material::RigidViscoplastic material;
    formsolve::state::State<dim>                 state;
    const formsolve::solver::Assembler<dim>      assembler;
    const formsolve::state::HistoryUpdate<dim>   update;
  };
} // namespace test
