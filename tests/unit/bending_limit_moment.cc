// Plane-strain pure bending of a rigid-perfectly-plastic strip: the limit
// moment from the computed dissipation, M = P / (2 omega), against the closed
// form (2/sqrt 3) sigma0 b t^2 / 4. Locking elements overshoot it.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/cell_kinematics.h>
#include <formsolve/solver/assembler.h>
#include <formsolve/solver/mumps_solver.h>
#include <formsolve/solver/newton_solver.h>

#include "check.h"
#include "toy_problem.h"

using namespace dealii;
using namespace formsolve;

namespace
{
  const double L = 4, b = 1, t = 1, sigma0 = 100, omega = 0.1, dt = 1e-3;

  class Bending : public test::ToyProblem
  {
  public:
    Bending(const unsigned int degree,
            const unsigned int layers,
            const unsigned int refinements)
        : tria(MPI_COMM_WORLD)
        , fe(FE_Q<3>(degree), 3)
        , dof_handler(tria)
        , mapping(degree)
        , material(material_parameters())
        , kinematics(false)
        , assembler(material, kinematics, mapping, degree)
        , linear(linear_parameters(), true)
    {
      parameters::Geometry g;
      g.model        = model::Model::full;
      g.blank_shape  = parameters::BlankShape::rectangle;
      g.blank_length = L;
      g.blank_width  = b;
      g.thickness    = t;
      parameters::Mesh m{degree, layers, refinements};
      geometry::create_blank_mesh(g, m, tria);
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      make_constraints(bc, true);
      make_constraints(homogeneous, false);

      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, homogeneous, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 MPI_COMM_WORLD,
                                                 relevant);
      matrix.reinit(owned, owned, dsp, MPI_COMM_WORLD);
      residual.reinit(owned, MPI_COMM_WORLD);
      ghost.reinit(owned, relevant, MPI_COMM_WORLD);
      for (const auto &cell : tria.active_cell_iterators())
        history.initialize(cell, QGauss<3>(degree + 1).size());
    }

    /// Solve; return the limit moment from the dissipation.
    double moment()
    {
      VectorType v(owned, MPI_COMM_WORLD);
      bc.distribute(v);
      parameters::NonlinearSolver p;
      p.residual_tolerance    = 1e-9;
      p.correction_tolerance  = 1e-9;
      p.max_line_search_steps = 8;
      const auto report =
        solve_from(solver::NewtonSolver(p,
                                        ConditionalOStream(std::cout, false)),
                   v);
      test::close("Newton converged", report.converged, 1, 0);
      ghost = v;
      return internal_power() / (2 * omega);
    }

    /// Plastic power int sigma' : D dV plus the volumetric term (W = N
    /// mm/s).
    double internal_power() const
    {
      const unsigned int                 degree = fe.degree;
      const QGauss<3>                    full(degree + 1), reduced(degree);
      model::CellKinematics<3>           kf(kinematics, mapping, fe, full);
      model::CellKinematics<3>           kr(kinematics, mapping, fe, reduced);
      std::vector<SymmetricTensor<2, 3>> D, Dr;
      double                             power = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            kf.reinit(cell);
            kr.reinit(cell);
            kf.rates(ghost, D);
            kr.rates(ghost, Dr);
            const auto h = history.get_data(cell);
            for (unsigned int q = 0; q < kf.n_points(); ++q)
              power += material.evaluate(D[q], h[q]->strain, dt, false)
                         .deviatoric_stress *
                       D[q] * kf.dV(q);
            for (unsigned int q = 0; q < kr.n_points(); ++q)
              power += material.bulk_viscosity() * trace(Dr[q]) * trace(Dr[q]) *
                       kr.dV(q);
          }
      return Utilities::MPI::sum(power, MPI_COMM_WORLD);
    }

    double assemble(const VectorType &v, const bool newton) override
    {
      ghost = v;
      scale = assembler.assemble_body(dof_handler,
                                      mapping,
                                      homogeneous,
                                      ghost,
                                      history,
                                      dt,
                                      newton,
                                      &matrix,
                                      residual);
      return residual.l2_norm();
    }
    double force_scale() const override { return scale; }
    double directional_derivative(const VectorType &w) const override
    {
      return residual * w;
    }
    unsigned int linear_solve(VectorType &dv) override
    {
      VectorType rhs(residual);
      rhs *= -1.;
      const auto its = linear.solve(matrix, dv, rhs);
      homogeneous.distribute(dv);
      return its;
    }

  private:
    static parameters::Material material_parameters()
    {
      parameters::Material m; // perfectly plastic, sigma_0
      m.strength_coefficient = sigma0;
      m.hardening_exponent   = 0;
      m.limiting_strain_rate = 1e-7;
      return m;
    }
    static parameters::LinearSolver linear_parameters()
    {
      return parameters::LinearSolver(); // direct, MUMPS
    }

    // Ends x = -+L/2 rotate: v_x = -+omega (z - t/2); plane strain: v_y = 0
    // everywhere; v_z = 0 at the ends' mid-plane removes the rigid z motion.
    void make_constraints(AffineConstraints<double> &c, const bool values)
    {
      std::map<types::global_dof_index, Point<3>> points;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
      c.clear();
      c.reinit(relevant);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const unsigned int comp = fe.system_to_component_index(i).first;
                const Point<3>    &x    = points[dofs[i]];
                const bool end = std::abs(std::abs(x[0]) - L / 2) < 1e-9;
                double     value;
                if (comp == 1)
                  value = 0;
                else if (comp == 0 && end)
                  value = (x[0] > 0 ? 1 : -1) * omega * (x[2] - t / 2);
                else if (comp == 2 && end && std::abs(x[2] - t / 2) < 1e-9)
                  value = 0;
                else
                  continue;
                if (!c.is_constrained(dofs[i]))
                  {
                    c.add_line(dofs[i]);
                    c.set_inhomogeneity(dofs[i], values ? value : 0.);
                  }
              }
          }
      c.close();
    }

    parallel::distributed::Triangulation<3> tria;
    FESystem<3>                             fe;
    DoFHandler<3>                           dof_handler;
    MappingQ<3>                             mapping;
    IndexSet                                owned, relevant;
    AffineConstraints<double>               bc, homogeneous;
    material::RigidViscoplastic             material;
    model::Kinematics<3>                    kinematics;
    solver::Assembler<3>                    assembler;
    solver::HistoryStorage<3>               history;
    solver::MatrixType                      matrix;
    VectorType                              residual, ghost;
    solver::MumpsSolver                     linear;
    double                                  scale = 0;
  };
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double exact = 2. / std::sqrt(3.) * sigma0 * b * t * t / 4.;
  std::cout << "closed-form limit moment: " << exact << " N mm\n";
  for (const auto &[degree, layers] : {std::pair{2u, 2u}, std::pair{1u, 4u}})
    {
      Bending      strip(degree, layers, 2);
      const double M = strip.moment();
      std::cout << "Q" << degree << ", " << layers << " layers: M = " << M
                << " N mm, relative error " << (M - exact) / exact << "\n";
      test::close("Q" + std::to_string(degree) + " " + std::to_string(layers) +
                    " layers: M / M_exact",
                  M / exact,
                  1.,
                  0.03);
    }
  return test::result();
}
