// The Linear solver subsection (declare, parse, validate); the other
// solver subsections are in solvers.cc.
#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/solvers.h>

#include <unistd.h>

#include <filesystem>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<UnsymmetricFactors> unsymmetric_names{
        {"LU", UnsymmetricFactors::lu},
        {"symmetric part", UnsymmetricFactors::symmetric_part}};
      /// true: METIS's nested dissection; false: MUMPS's automatic choice.
      const Choice<bool> ordering_names{{"METIS", true}, {"automatic", false}};
      const Choice<FactorPrecision> precision_names{
        {"double", FactorPrecision::double_precision},
        {"single", FactorPrecision::single_precision}};
    } // namespace

    void LinearSolver::declare(Declarations &d)
    {
      const Subsection s(d, "Linear solver");
      declare_factors(d);
      declare_approximate_factors(d);
      declare_reuse(d);
      d.add("Condition estimate iterations",
            condition_iterations,
            whole_number(0),
            "Diagnostics: after every linear solve, this many unpreconditioned "
            "CG iterations on the system matrix give a Lanczos estimate of its "
            "condition number (solver.csv column condition_estimate; a lower "
            "bound, meaningful for symmetric systems, i.e. without friction). "
            "0: off.");
    }

    void LinearSolver::declare_factors(Declarations &d)
    {
      d.add("Symmetric factorisation",
            symmetric_factorisation,
            "Factorise as LDL^T (one triangle stored, about half the "
            "memory and time) whenever the tangent is symmetric, i.e. without "
            "friction on every tool; "
            "otherwise as Unsymmetric tangent says. false: always LU.");
      d.add(
        "Unsymmetric tangent",
        unsymmetric_factors,
        unsymmetric_names,
        "A tangent K that is not symmetric (sliding friction). LU: factorise K "
        "(exact factors, solved "
        "by one substitution). symmetric part: factorise LDL^T of the "
        "symmetric part (K + K^T)/2 (about 0.6x the memory of LU and faster) "
        "and solve K by GMRES preconditioned by it, to Reuse tolerance "
        "within 30 iterations; Newton keeps the exact tangent. "
        "On several ranks, entries whose transpose lies on another rank are "
        "taken from K's lower triangle.");
      d.add("Ordering",
            metis_order,
            ordering_names,
            "Pivot order. METIS: nested dissection of the matrix graph by "
            "METIS_NodeND (Debian's MUMPS is built without METIS; the order is "
            "computed by formsolve and passed in); automatic: MUMPS's own "
            "choice (PORD on Debian).");
      d.add(
        "Refinement steps",
        refinement_steps,
        whole_number(0, 100),
        "At most this many steps of iterative refinement after each "
        "solve, stopped when the componentwise backward error is at round-off "
        "(MUMPS ICNTL(10)). 0: none.");
      d.add(
        "Out-of-core directory",
        out_of_core_directory,
        text("a folder path (relative to the working directory), or empty"),
        "An existing, writable directory (absolute, "
        "or relative to the working directory) where MUMPS writes the "
        "factors during each factorisation and reads them back for every "
        "solve (out-of-core, ICNTL(22) = 1): the run holds only MUMPS's "
        "working memory, at the price of disk traffic (doc/performance.md). "
        "The files are removed when the factors are dropped; a run that is "
        "killed leaves files named formsolve_* there. Empty: the factors stay "
        "in memory.");
    }

    void LinearSolver::declare_approximate_factors(Declarations &d)
    {
      d.add(
        "Factor precision",
        factor_precision,
        precision_names,
        "The arithmetic of the factorisation. double: "
        "the factors solve to round-off. single: MUMPS factorises the matrix "
        "rounded to single precision (half the factor memory, fewer "
        "operands to move); every solve is then GMRES in double precision "
        "preconditioned by these factors, to Reuse tolerance within 20 "
        "iterations (doc/performance.md).");
      d.add(
        "Low-rank tolerance",
        low_rank_tolerance,
        number("", 0),
        "Block low-rank (BLR) factorisation with this "
        "dropping tolerance (-, relative to the scaled matrix; MUMPS "
        "ICNTL(35) = 2, CNTL(7)), e.g. 1e-8. The factors are then stored "
        "compressed and are approximate: every solve is GMRES preconditioned "
        "by them, to Reuse tolerance within Low-rank iterations. 0: full-rank "
        "factors (exact up to round-off).");
      d.add("Low-rank iterations",
            low_rank_iterations,
            whole_number(1, 1000),
            "GMRES iterations allowed with low-rank factors before the linear "
            "solve fails (the Newton step is then cut back).");
    }

    void LinearSolver::declare_reuse(Declarations &d)
    {
      d.add(
        "Reuse factorisation iterations",
        reuse_iterations,
        whole_number(0, 1000),
        "Solve a new matrix by GMRES preconditioned with the "
        "last numeric factorisation (of an earlier Newton iteration or step) "
        "while GMRES converges within this many iterations; otherwise, or "
        "when the sparsity pattern changed, factorise afresh. 0: a fresh "
        "factorisation for every matrix.");
      d.add(
        "Reuse velocity change",
        reuse_velocity_change,
        number("-", 0),
        "Reuse factorisation iterations > 0: try the last factors on a new "
        "matrix only if both belong to the same Newton solve and the "
        "velocities they were assembled at differ by at most this fraction, "
        "|v - v_f| <= value |v| (-); otherwise factorise at once. Early "
        "iterations of a step change the tangent too much for GMRES to "
        "converge on old factors, and each such failed attempt costs Reuse "
        "factorisation iterations substitutions (doc/performance.md). 0: "
        "always try, also across solves and steps.");
      d.add("Reuse tolerance",
            reuse_tolerance,
            number("-", 0),
            "Relative residual |b - A x|/|b| that GMRES with a reused "
            "factorisation must reach (-); a fresh factorisation solves to "
            "round-off.");
    }


    void LinearSolver::validate() const
    {
      require(reuse_tolerance > 0 && reuse_tolerance < 1,
              "Linear solver/Reuse tolerance",
              "must lie in (0, 1)");
      require(low_rank_tolerance < 1,
              "Linear solver/Low-rank tolerance",
              "must lie in [0, 1)");
      // MUMPS's refinement stops on a backward-error test: a preconditioner
      // that changes between applications, which GMRES does not allow.
      require(low_rank_tolerance == 0 || refinement_steps == 0,
              "Linear solver/Low-rank tolerance",
              "> 0 needs Refinement steps = 0 (GMRES refines the solve)");
      const bool symmetric_part =
        unsymmetric_factors == UnsymmetricFactors::symmetric_part;
      require(!symmetric_part || symmetric_factorisation,
              "Linear solver/Unsymmetric tangent",
              "= symmetric part needs Symmetric factorisation = true");
      require(!symmetric_part || refinement_steps == 0,
              "Linear solver/Unsymmetric tangent",
              "= symmetric part needs Refinement steps = 0 (GMRES refines "
              "the solve)");
      const bool single = factor_precision == FactorPrecision::single_precision;
      require(!single || refinement_steps == 0,
              "Linear solver/Factor precision",
              "= single needs Refinement steps = 0 (GMRES refines the solve)");
      if (!out_of_core_directory.empty())
        {
          const std::string entry = "Linear solver/Out-of-core directory";
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
