// Subsections "Time stepping" (with step control), "Nonlinear solver" and
// "Linear solver".
#pragma once

#include <string>

namespace formsolve
{
  namespace parameters
  {
    class Declarations;

    enum class EndOfRun
    {
      stroke,         // the punch stroke is reached
      holder_release, // ... or the blank rim has left the blank holder
      draw_through    // ... or the blank lies wholly inside the die opening
    };

    struct TimeStepping
    {
      double       time_step         = 0.25; // s, nominal and largest
      double       minimum_time_step = 1e-3; // s
      double       cutback_factor    = 0.5;  // dt <- this * dt on failure
      double       growth_factor     = 1.5;  // dt <- this * dt after easy steps
      unsigned int easy_iterations   = 8;    // Newton its of an easy step
      unsigned int regrowth_steps    = 4; // growth after this many calm steps
      unsigned int max_cutbacks      = 8; // per step
      EndOfRun     end_of_run        = EndOfRun::stroke;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;
    };

    /// Linearisation of the flow law in the Newton tangent.
    enum class Tangent
    {
      newton,         // d s'/dD of the velocity-only law
      stress_velocity // the stress direction linearised with the velocity
    };

    /// What the correction tolerance is compared with.
    enum class CorrectionMeasure
    {
      last,       // the last correction |dv|
      contraction // the error it leaves, from the contraction of full steps
    };

    /// The first iterate of a step.
    enum class Predictor
    {
      previous_velocity, // the previous step's velocity
      keep_contact       // the same, with nodes in contact kept on their tool
    };

    /// Where the first step's Newton iteration starts (doc/theory.md
    /// section 8b).
    enum class FirstStepStart
    {
      rest,        // zero velocity
      coarser_mesh // the step solved first on the mesh one level coarser
    };

    struct NonlinearSolver
    {
      Tangent           tangent               = Tangent::stress_velocity;
      unsigned int      max_iterations        = 60;
      double            residual_tolerance    = 1e-5;
      double            correction_tolerance  = 1e-5;
      CorrectionMeasure correction_measure    = CorrectionMeasure::contraction;
      Predictor         predictor             = Predictor::keep_contact;
      unsigned int      max_line_search_steps = 6;
      /// Nonmonotone line search: a trial must beat the largest merit of
      /// the last line_search_memory iterates; 1 is monotone.
      unsigned int line_search_memory = 3;
      /// The tangent of an expected last iterate assembled only if needed.
      bool           deferred_tangent  = true;
      double         forcing           = 0; // inexact Newton; 0: off
      unsigned int   picard_iterations = 0;
      bool           picard_fallback   = true;
      bool           log_iterations    = false;
      FirstStepStart first_step_start  = FirstStepStart::coarser_mesh;
      /// The coarser mesh is used only when its cells are on average no
      /// longer than this many sheet thicknesses in the plane.
      double coarse_cell_size_limit = 2;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;

    private:
      void declare_convergence(Declarations &d);
      void declare_iterations(Declarations &d);
      void declare_first_step(Declarations &d);
    };

    /// MUMPS: how a tangent that is not symmetric (sliding friction) is
    /// factorised.
    enum class UnsymmetricFactors
    {
      lu,            // LU of the tangent: exact factors
      symmetric_part // LDL^T of (K + K^T)/2, GMRES on K preconditioned by it
    };
    /// MUMPS: the arithmetic of the factors.
    enum class FactorPrecision
    {
      double_precision, // exact factors up to round-off
      single_precision  // float factors, GMRES preconditioned by them
    };

    /// The linear solver (MUMPS, solver/mumps_solver.h).
    struct LinearSolver
    {
      /// LDL^T when the tangent is symmetric.
      bool symmetric_factorisation = true;
      /// The factors of an unsymmetric tangent.
      UnsymmetricFactors unsymmetric_factors = UnsymmetricFactors::lu;
      bool               metis_order = true; // else MUMPS's automatic (PORD)
      unsigned int       refinement_steps     = 0; // MUMPS iterative refinement
      unsigned int       condition_iterations = 0; // Lanczos estimate, 0: off
      /// GMRES iterations allowed with an older factorisation as
      /// preconditioner before refactorising; 0: factorise every matrix.
      unsigned int reuse_iterations = 0;
      double       reuse_tolerance  = 1e-10; // relative residual of that GMRES
      /// Largest |v - v_f|/|v| between the velocity of a new matrix and that
      /// of the factorised one for which reuse is tried (0: always tried).
      double reuse_velocity_change = 0;
      /// Block low-rank dropping tolerance (-); 0: full-rank factors.
      double low_rank_tolerance = 0;
      /// GMRES iterations allowed with the low-rank factors.
      unsigned int low_rank_iterations = 20;
      /// Out-of-core factors in this directory; empty: in memory.
      std::string out_of_core_directory;
      /// Single-precision factors as GMRES's preconditioner.
      FactorPrecision factor_precision = FactorPrecision::double_precision;

      /// Declares the entries, bound to these members.
      void declare(Declarations &d);
      void validate() const;

    private:
      void declare_factors(Declarations &d);
      void declare_approximate_factors(Declarations &d);
      void declare_reuse(Declarations &d);
    };
  } // namespace parameters
} // namespace formsolve
