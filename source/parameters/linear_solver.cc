// The Linear solver subsection (declare, parse, validate); the other
// solver subsections are in solvers.cc.
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/solvers.h>

#include <unistd.h>

#include <filesystem>

namespace formsolve
{
  namespace parameters
  {
    using namespace dealii::Patterns;
    void LinearSolver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry(
        "Type",
        "direct",
        Selection("direct|iterative"),
        "direct: a sparse direct solver (Direct solver); iterative: a "
        "Krylov solver with ML algebraic multigrid.");
      prm.declare_entry(
        "Direct solver",
        "MUMPS",
        Selection("MUMPS|Amesos MUMPS|KLU"),
        "MUMPS: MUMPS called directly, each rank passing its own rows, with "
        "the options below; Amesos MUMPS: MUMPS through Trilinos Amesos "
        "(unsymmetric LU, MUMPS's automatic ordering: the earlier default); "
        "KLU: Amesos KLU, serial (the matrix is gathered on one rank).");
      prm.declare_entry(
        "Symmetric factorisation",
        "true",
        Bool(),
        "MUMPS: factorise as LDL^T (one triangle stored, about half the "
        "memory and time) whenever the tangent is symmetric, i.e. without "
        "friction or with Nonlinear solver/Friction tangent = symmetrised; "
        "otherwise as Unsymmetric tangent says. false: always LU.");
      prm.declare_entry(
        "Unsymmetric tangent",
        "LU",
        Selection("LU|symmetric part"),
        "MUMPS, a tangent K that is not symmetric (sliding friction with "
        "Friction tangent = exact). LU: factorise K (exact factors, solved "
        "by one substitution). symmetric part: factorise LDL^T of the "
        "symmetric part (K + K^T)/2 (about 0.6x the memory of LU and faster) "
        "and solve K by GMRES preconditioned by it, to Reuse tolerance "
        "within Symmetric-part iterations; Newton keeps the exact tangent. "
        "On several ranks, entries whose transpose lies on another rank are "
        "taken from K's lower triangle.");
      prm.declare_entry(
        "Symmetric-part iterations",
        "30",
        Integer(1, 1000),
        "Unsymmetric tangent = symmetric part: GMRES iterations allowed "
        "before the linear solve fails (the Newton step is then cut back).");
      prm.declare_entry(
        "Ordering",
        "METIS",
        Selection("METIS|automatic"),
        "MUMPS: pivot order. METIS: nested dissection of the matrix graph by "
        "METIS_NodeND (Debian's MUMPS is built without METIS; the order is "
        "computed by formsolve and passed in); automatic: MUMPS's own "
        "choice (PORD on Debian).");
      prm.declare_entry(
        "Refinement steps",
        "0",
        Integer(0, 100),
        "MUMPS: at most this many steps of iterative refinement after each "
        "solve, stopped when the componentwise backward error is at round-off "
        "(MUMPS ICNTL(10)). 0: none.");
      prm.declare_entry("Iterative solver",
                        "GMRES",
                        Selection("GMRES|CG"),
                        "Krylov method (CG only for frictionless contact: the "
                        "friction tangent is not symmetric).");
      prm.declare_entry(
        "Tolerance",
        "1e-8",
        Double(0),
        "Relative residual tolerance of the iterative solver (-).");
      prm.declare_entry("Max iterations",
                        "2000",
                        Integer(1),
                        "Iteration limit of the iterative solver.");
      prm.declare_entry(
        "AMG null space",
        "rigid-body modes",
        Selection("rigid-body modes|translations"),
        "Type = iterative: the near null space ML coarsens with. rigid-body "
        "modes: translations and rotations of the current configuration "
        "(6 in 3-D, 3 in 2-D); translations: dim constant modes.");
      prm.declare_entry(
        "AMG smoother",
        "Chebyshev",
        Selection("Chebyshev|symmetric Gauss-Seidel|line Gauss-Seidel"),
        "Type = iterative: ML's smoother (2 sweeps). line Gauss-Seidel "
        "solves the nodes along lines it detects from the coordinates (the "
        "thickness direction of a sheet) together.");
      prm.declare_entry(
        "Fallback to direct",
        "true",
        Bool(),
        "Type = iterative: a solve that does not reach Tolerance within Max "
        "iterations is done by the direct solver (Direct solver) instead; it "
        "counts as a factorisation. false: the Newton solve fails (and the "
        "step is cut back).");
      prm.declare_entry(
        "Condition estimate iterations",
        "0",
        Integer(0),
        "Diagnostics: after every linear solve, this many unpreconditioned "
        "CG iterations on the system matrix give a Lanczos estimate of its "
        "condition number (history.csv column condition_estimate; a lower "
        "bound, meaningful for symmetric systems, i.e. without friction). "
        "0: off.");
      prm.declare_entry(
        "Reuse factorisation iterations",
        "0",
        Integer(0, 1000),
        "Direct solver: solve a new matrix by GMRES preconditioned with the "
        "last numeric factorisation (of an earlier Newton iteration or step) "
        "while GMRES converges within this many iterations; otherwise, or "
        "when the sparsity pattern changed, factorise afresh. 0: a fresh "
        "factorisation for every matrix.");
      prm.declare_entry(
        "Reuse velocity change",
        "0",
        Double(0),
        "Reuse factorisation iterations > 0: try the last factors on a new "
        "matrix only if both belong to the same Newton solve and the "
        "velocities they were assembled at differ by at most this fraction, "
        "|v - v_f| <= value |v| (-); otherwise factorise at once. Early "
        "iterations of a step change the tangent too much for GMRES to "
        "converge on old factors, and each such failed attempt costs Reuse "
        "factorisation iterations substitutions (doc/performance.md). 0: "
        "always try, also across solves and steps.");
      prm.declare_entry(
        "Reuse tolerance",
        "1e-10",
        Double(0),
        "Relative residual |b - A x|/|b| that GMRES with a reused "
        "factorisation must reach (-); a fresh factorisation solves to "
        "round-off.");
      prm.declare_entry(
        "Low-rank tolerance",
        "0",
        Double(0),
        "Direct solver = MUMPS: block low-rank (BLR) factorisation with this "
        "dropping tolerance (-, relative to the scaled matrix; MUMPS "
        "ICNTL(35) = 2, CNTL(7)), e.g. 1e-8. The factors are then stored "
        "compressed and are approximate: every solve is GMRES preconditioned "
        "by them, to Reuse tolerance within Low-rank iterations. 0: full-rank "
        "factors (exact up to round-off).");
      prm.declare_entry(
        "Low-rank iterations",
        "20",
        Integer(1, 1000),
        "GMRES iterations allowed with low-rank factors before the linear "
        "solve fails (the Newton step is then cut back).");
      prm.declare_entry(
        "Out-of-core directory",
        "",
        Anything(),
        "Direct solver = MUMPS: an existing, writable directory (absolute, "
        "or relative to the working directory) where MUMPS writes the "
        "factors during each factorisation and reads them back for every "
        "solve (out-of-core, ICNTL(22) = 1): the run holds only MUMPS's "
        "working memory, at the price of disk traffic (doc/performance.md). "
        "The files are removed when the factors are dropped; a run that is "
        "killed leaves files named formsolve_* there. Empty: the factors stay "
        "in memory.");
      prm.declare_entry(
        "Factor precision",
        "double",
        Selection("double|single"),
        "Direct solver = MUMPS: the arithmetic of the factorisation. double: "
        "the factors solve to round-off. single: MUMPS factorises the matrix "
        "rounded to single precision (half the factor memory, fewer "
        "operands to move); every solve is then GMRES in double precision "
        "preconditioned by these factors, to Reuse tolerance within "
        "Single-precision iterations (doc/performance.md).");
      prm.declare_entry(
        "Single-precision iterations",
        "20",
        Integer(1, 1000),
        "Factor precision = single: GMRES iterations allowed before the "
        "linear solve fails (the Newton step is then cut back).");
      prm.declare_entry(
        "Narrow BLAS calls",
        "true",
        Bool(),
        "true: BLAS-3 calls with one or two columns (GEMM, TRSM), which "
        "MUMPS's substitutions make for every right-hand side, go column by "
        "column to the matrix-vector kernels (GEMV, TRSV) of the same BLAS; "
        "Debian's OpenBLAS packs the whole matrix for them. Every caller in "
        "the process is affected, and only in speed and round-off "
        "(doc/performance.md, \"Narrow BLAS calls\"). false: every call as "
        "made.");
      prm.leave_subsection();
    }

    void LinearSolver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type = prm.get("Type") == "direct" ? LinearSolverType::direct
                                         : LinearSolverType::iterative;
      const std::string direct   = prm.get("Direct solver");
      direct_solver              = direct == "MUMPS" ? DirectSolver::mumps
                                   : direct == "Amesos MUMPS" ? DirectSolver::amesos_mumps
                                                              : DirectSolver::klu;
      symmetric_factorisation    = prm.get_bool("Symmetric factorisation");
      unsymmetric_factors        = prm.get("Unsymmetric tangent") == "LU"
                                     ? UnsymmetricFactors::lu
                                     : UnsymmetricFactors::symmetric_part;
      symmetric_part_iterations  = prm.get_integer("Symmetric-part iterations");
      metis_order                = prm.get("Ordering") == "METIS";
      refinement_steps           = prm.get_integer("Refinement steps");
      iterative_solver           = prm.get("Iterative solver") == "CG"
                                     ? IterativeSolver::cg
                                     : IterativeSolver::gmres;
      tolerance                  = prm.get_double("Tolerance");
      amg_null_space             = prm.get("AMG null space") == "translations"
                                     ? AmgNullSpace::translations
                                     : AmgNullSpace::rigid_body_modes;
      const std::string smoother = prm.get("AMG smoother");
      amg_smoother          = smoother == "Chebyshev" ? AmgSmoother::chebyshev
                              : smoother == "symmetric Gauss-Seidel"
                                ? AmgSmoother::symmetric_gauss_seidel
                                : AmgSmoother::line_gauss_seidel;
      direct_fallback       = prm.get_bool("Fallback to direct");
      max_iterations        = prm.get_integer("Max iterations");
      condition_iterations  = prm.get_integer("Condition estimate iterations");
      reuse_iterations      = prm.get_integer("Reuse factorisation iterations");
      reuse_tolerance       = prm.get_double("Reuse tolerance");
      reuse_velocity_change = prm.get_double("Reuse velocity change");
      low_rank_tolerance    = prm.get_double("Low-rank tolerance");
      low_rank_iterations   = prm.get_integer("Low-rank iterations");
      out_of_core_directory = prm.get("Out-of-core directory");
      factor_precision      = prm.get("Factor precision") == "single"
                                ? FactorPrecision::single_precision
                                : FactorPrecision::double_precision;
      single_precision_iterations =
        prm.get_integer("Single-precision iterations");
      narrow_blas_calls = prm.get_bool("Narrow BLAS calls");
      prm.leave_subsection();
    }

    void LinearSolver::validate() const
    {
      require(tolerance > 0 && tolerance < 1,
              "Linear solver/Tolerance",
              "must lie in (0, 1)");
      require(reuse_tolerance > 0 && reuse_tolerance < 1,
              "Linear solver/Reuse tolerance",
              "must lie in (0, 1)");
      require(low_rank_tolerance < 1,
              "Linear solver/Low-rank tolerance",
              "must lie in [0, 1)");
      require(low_rank_tolerance == 0 || (type == LinearSolverType::direct &&
                                          direct_solver == DirectSolver::mumps),
              "Linear solver/Low-rank tolerance",
              "needs Type = direct and Direct solver = MUMPS");
      // MUMPS's refinement stops on a backward-error test: a preconditioner
      // that changes between applications, which GMRES does not allow.
      require(low_rank_tolerance == 0 || refinement_steps == 0,
              "Linear solver/Low-rank tolerance",
              "> 0 needs Refinement steps = 0 (GMRES refines the solve)");
      const bool symmetric_part =
        unsymmetric_factors == UnsymmetricFactors::symmetric_part;
      require(!symmetric_part || (type == LinearSolverType::direct &&
                                  direct_solver == DirectSolver::mumps &&
                                  symmetric_factorisation),
              "Linear solver/Unsymmetric tangent",
              "= symmetric part needs Type = direct, Direct solver = MUMPS "
              "and Symmetric factorisation = true");
      require(!symmetric_part || refinement_steps == 0,
              "Linear solver/Unsymmetric tangent",
              "= symmetric part needs Refinement steps = 0 (GMRES refines "
              "the solve)");
      const bool single = factor_precision == FactorPrecision::single_precision;
      require(!single || (type == LinearSolverType::direct &&
                          direct_solver == DirectSolver::mumps),
              "Linear solver/Factor precision",
              "= single needs Type = direct and Direct solver = MUMPS");
      require(!single || refinement_steps == 0,
              "Linear solver/Factor precision",
              "= single needs Refinement steps = 0 (GMRES refines the solve)");
      if (!out_of_core_directory.empty())
        {
          const std::string entry = "Linear solver/Out-of-core directory";
          require(type == LinearSolverType::direct &&
                    direct_solver == DirectSolver::mumps,
                  entry,
                  "needs Type = direct and Direct solver = MUMPS");
          // MUMPS keeps the name in a 256-character field.
          require(out_of_core_directory.size() < 200,
                  entry,
                  "'" + out_of_core_directory +
                    "' is too long for MUMPS (at most 199 characters)");
          std::error_code error;
          require(std::filesystem::is_directory(out_of_core_directory, error) &&
                    access(out_of_core_directory.c_str(), W_OK | X_OK) == 0,
                  entry,
                  "'" + out_of_core_directory +
                    "' is not an existing, writable directory");
        }
    }
  } // namespace parameters
} // namespace formsolve
