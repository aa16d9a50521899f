// Where a trim cuts the formed part: the half-spaces, plan-view curve and
// surface of the Trimming subsection as one function of a point, positive
// where the part is kept. Its size is a distance (mm) near the cut, which
// the refinement along the trim line measures the cut edge by.
#pragma once

#include <deal.II/base/point.h>

#include <formsolve/model/model.h>
#include <formsolve/parameters/trimming.h>

#include <mpi.h>

#include <memory>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    class TriangleSurface;
  }

  namespace trimming
  {
    template <int dim>
    class TrimShape
    {
    public:
      /// Reads the curve and surface files on rank 0 of @p comm and shares
      /// them; errors name the file (on every rank).
      TrimShape(const parameters::Trimming &trimming,
                const model::Model          model,
                MPI_Comm                    comm);
      ~TrimShape();

      /// The smallest of the cuts' signed distances at @p p (model
      /// coordinates, mm): > 0 where every cut keeps the part.
      double side(const dealii::Point<dim> &p) const;

      bool empty() const { return planes.empty() && curve.empty() && !surface; }

    private:
      struct Plane
      {
        dealii::Tensor<1, dim> normal; // unit, towards the kept side
        double                 offset; // normal . p - offset > 0: kept
      };
      double curve_side(const dealii::Point<2> &p) const;

      std::vector<Plane>                      planes;
      std::vector<dealii::Point<2>>           curve; // plan view (x, y)
      bool                                    closed = false;
      parameters::CurveSide                   curve_keeps;
      parameters::SurfaceSide                 surface_keeps;
      std::unique_ptr<tools::TriangleSurface> surface;
    };
  } // namespace trimming
} // namespace formsolve
