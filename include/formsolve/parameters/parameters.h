// All .prm subsections of a run: one struct each (declare, validate), and
// the cross-subsection checks.
#pragma once

#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/geometry.h>
#include <formsolve/parameters/material.h>
#include <formsolve/parameters/output.h>
#include <formsolve/parameters/refinement.h>
#include <formsolve/parameters/solvers.h>
#include <formsolve/parameters/split.h>
#include <formsolve/parameters/springback.h>
#include <formsolve/parameters/tools.h>
#include <formsolve/parameters/trimming.h>

namespace formsolve
{
  namespace parameters
  {
    struct Run
    {
      Geometry        geometry;
      Mesh            mesh;
      MeshRefinement  refinement;
      Material        material;
      Tools           tools;
      Contact         contact;
      TimeStepping    time;
      NonlinearSolver nonlinear;
      LinearSolver    linear;
      Split           split;
      Trimming        trimming;
      Springback      springback;
      Output          output;

      /// Declares every subsection, bound to these members: reading the
      /// input fills them. The object must not move until then.
      void declare(Declarations &d);
      /// What follows from several entries once the input is read (the
      /// holder force by Siebel's rule).
      void complete();
      /// Cross-subsection checks; throws with a message naming the entries.
      void validate() const;
      /// Whether the Newton tangent is symmetric: every enabled tool is
      /// frictionless.
      bool symmetric_tangent() const;
    };
  } // namespace parameters
} // namespace formsolve
