// The body tangent through the material's general 6x6 tangent
// (RigidViscoplastic::tangent, CellTangent::add_general) equals the one from
// the isotropic product form, on a sheet with plastic and rigid points: with
// Newton's tangent, the secant one, and the stress-velocity tangent with dual
// directions from an accepted iterate. Axisymmetric and quarter models, 1 and
// 2 ranks. A wrong Mandel factor, a lost hoop term or a dual term with the
// wrong weight would show here.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <formsolve/forming/assembler.h>
#include <formsolve/forming/dual_stress.h>

#include "check.h"
#include "small_blank.h"

#include <cmath>

using namespace dealii;
using namespace formsolve;

namespace
{
  /// A velocity (mm/s) that stretches, shears and bends the blank, slow
  /// (rigid) near the axis or corner.
  template <int dim>
  class Flow : public Function<dim>
  {
  public:
    explicit Flow(const double scale)
        : Function<dim>(dim)
        , scale(scale)
    {}
    double value(const Point<dim> &x, const unsigned int c) const override
    {
      const double r = x[0] + (dim == 3 ? x[1] : 0.);
      const double f = scale * std::max(r - 3., 0.) * 0.05;
      if (c == dim - 1)
        return f * (0.3 * x[0] - 0.5 * x[dim - 1]);
      return f * (x[c] + 0.4 * x[dim - 1] * (c + 1));
    }

  private:
    double scale;
  };

  using solver::MatrixType;
  using solver::VectorType;

  template <int dim>
  void check(const std::string &name, const model::Model m)
  {
    test::SmallBlank<dim> blank(m, {1, 2, dim == 2 ? 4u : 2u});
    auto                 &state = blank.state;
    // Without the volumetric penalty, which would dwarf the deviatoric part
    // in any norm of K.
    parameters::Material p = blank.prm.material;
    p.volumetric_penalty   = 0;
    const material::RigidViscoplastic material(p);
    const solver::Assembler<dim>      product(material,
                                         state.kinematics,
                                         state.reference_mapping,
                                         1);
    solver::Assembler<dim>            general(material,
                                   state.kinematics,
                                   state.reference_mapping,
                                   1);
    general.use_general_tangent();

    for (const auto &cell : state.tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &h : state.history.get_data(cell))
          h->strain = 0.05 + 0.01 * cell->center()[0];

    DynamicSparsityPattern dsp(state.relevant);
    DoFTools::make_sparsity_pattern(state.dof_handler,
                                    dsp,
                                    state.constraints,
                                    false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               state.owned,
                                               state.comm,
                                               state.relevant);
    MatrixType K_product, K_general;
    K_product.reinit(state.owned, state.owned, dsp, state.comm);
    K_general.reinit(state.owned, state.owned, dsp, state.comm);
    VectorType r_product(state.owned, state.comm), r_general(r_product);

    const auto velocity = [&](const double scale) {
      VectorType v(state.owned, state.comm);
      VectorTools::interpolate(state.reference_mapping,
                               state.dof_handler,
                               Flow<dim>(scale),
                               v);
      state.constraints.distribute(v);
      VectorType ghosted(state.owned, state.relevant, state.comm);
      ghosted = v;
      return ghosted;
    };
    solver::DualStress dual;
    dual.reinit(state.tria.n_active_cells(), product.quadrature().size());
    // The accepted iterate of the dual directions, then a trial near it.
    product.assemble_body(state.dof_handler,
                          *state.mapping,
                          state.constraints,
                          velocity(1.),
                          state.history,
                          0.1,
                          true,
                          &K_product,
                          r_product,
                          &dual);
    dual.accept();

    for (const auto &[label, newton, with_dual] :
         {std::tuple{"Newton", true, false},
          std::tuple{"secant", false, false},
          std::tuple{"stress-velocity", true, true}})
      {
        const VectorType v = velocity(1.3);
        for (auto *a :
             {&product, static_cast<const solver::Assembler<dim> *>(&general)})
          a->assemble_body(state.dof_handler,
                           *state.mapping,
                           state.constraints,
                           v,
                           state.history,
                           0.1,
                           newton,
                           a == &product ? &K_product : &K_general,
                           a == &product ? r_product : r_general,
                           with_dual ? &dual : nullptr);
        const double scale = K_product.frobenius_norm();
        K_general.add(-1., K_product);
        r_general.add(-1., r_product);
        const double error    = K_general.frobenius_norm() / scale;
        const double residual = r_general.l2_norm();
        if (Utilities::MPI::this_mpi_process(state.comm) != 0)
          continue;
        test::close(name + ", " + label + ": |K_general - K_product| / |K|",
                    error,
                    0,
                    1e-13);
        test::close(name + ", " + label + ": the same residual",
                    residual,
                    0,
                    0);
        test::close(name + ", " + label + ": a tangent at all",
                    scale > 0,
                    1,
                    0);
      }
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("axisymmetric", model::Model::axisymmetric);
  check<3>("quarter", model::Model::quarter);
  return test::result();
}
