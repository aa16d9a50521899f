#include <formsolve/solver/amg_setup.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    std::unique_ptr<TrilinosWrappers::PreconditionAMG>
    make_amg(const TrilinosWrappers::SparseMatrix &A,
             const parameters::LinearSolver       &prm,
             const std::vector<std::vector<bool>> &constant_modes,
             NullSpace                            &null_space,
             const bool                            with_null_space)
    {
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      data.constant_modes        = constant_modes;
      Teuchos::ParameterList              list;
      std::unique_ptr<Epetra_MultiVector> translations;
      data.set_parameters(list, translations, A);
      // Checks on values that are the same on every rank (a rank without
      // DoFs has empty arrays): no rank may stop alone before ML's set-up.
      if (with_null_space)
        {
          AssertThrow(null_space.n_modes > 0,
                      ExcMessage("AMG: no null space for this matrix"));
          Assert(null_space.modes.size() == null_space.n_modes * A.local_size(),
                 ExcInternalError());
          list.set("PDE equations", static_cast<int>(null_space.n_components));
        }
      if (prm.amg_null_space == parameters::AmgNullSpace::rigid_body_modes)
        {
          list.set("null space: type", "pre-computed");
          list.set("null space: dimension",
                   static_cast<int>(null_space.n_modes));
          list.set("null space: vectors", null_space.modes.data());
        }
      if (prm.amg_smoother == parameters::AmgSmoother::symmetric_gauss_seidel)
        list.set("smoother: type", "symmetric Gauss-Seidel");
      else if (prm.amg_smoother == parameters::AmgSmoother::line_gauss_seidel)
        {
          list.set("smoother: type", "line Gauss-Seidel");
          list.set("smoother: line detection threshold", 0.1);
          list.set("x-coordinates", null_space.x.data());
          list.set("y-coordinates", null_space.y.data());
          list.set("z-coordinates", null_space.z.data());
        }
      amg->initialize(A, list);
      return amg;
    }
  } // namespace solver
} // namespace formsolve
