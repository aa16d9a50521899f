// Whether the sheet has split, watched after every converged step by three
// measures: a column past the forming limit curve, a neck (the thinnest
// column thinning much faster than its neighbours while the punch force
// falls), and the fracture criterion reaching 1 (doc/theory.md, section
// 11c). Each measure's first occurrence is kept; the first of those that
// Split/Measures names is the split.
#pragma once

#include <deal.II/base/point.h>

#include <formsolve/model/model.h>
#include <formsolve/parameters/split.h>
#include <formsolve/postprocess/sheet_measures.h>

#include <map>
#include <string>
#include <vector>

namespace formsolve
{
  namespace postprocess
  {
    enum class SplitMeasure : unsigned int
    {
      forming_limit = 0,
      neck          = 1,
      fracture      = 2
    };

    /// "forming limit", "neck", "fracture criterion" (as in Split/Measures).
    std::string split_measure_name(const SplitMeasure m);

    /// Where and when a measure was first met.
    template <int dim>
    struct SplitEvent
    {
      double             travel = -1; // punch travel (mm); < 0: not met
      double             reference_radius = 0, reference_angle = 0;
      dealii::Point<dim> location; // current mid-surface point (mm)
      /// How strongly: the FLC usage (1 - margin), the neck's localisation,
      /// or the damage value.
      double value = 0;

      bool met() const { return travel >= 0; }
      /// "R0 = 20.5 mm (now r = 21.3, z = -19.8 mm)", with the angle from x
      /// in 3-D, "X0 = ... (now x = ..., z = ...)" in plane strain.
      std::string where(const model::Model m) const;
    };

    template <int dim>
    class SplitWatch
    {
    public:
      SplitWatch(const parameters::Split &split, const double thickness);

      /// After a converged step (collective): checks the FLC margin and the
      /// neck on @p sheet as just measured, at punch travel @p travel with
      /// @p punch_force solved in the step; @p fracture: the fracture
      /// criterion's event if it reached 1 in this step. Returns the
      /// measures first met in this step.
      std::vector<SplitMeasure> observe(const SheetMeasures<dim> &sheet,
                                        const double              travel,
                                        const double              punch_force,
                                        const SplitEvent<dim>    &fracture,
                                        const MPI_Comm            comm);

      const SplitEvent<dim> &event(const SplitMeasure m) const
      {
        return events[static_cast<unsigned int>(m)];
      }
      /// Whether @p m marks a split (Split/Measures).
      bool marks_split(const SplitMeasure m) const;
      /// Whether the sheet has split, and the measure that first said so.
      bool         split() const;
      SplitMeasure split_measure() const;
      /// The split's event (travel < 0: no split).
      const SplitEvent<dim> &first() const;

      /// The running values, for a checkpoint, and back.
      std::map<std::string, std::string> save() const;
      void load(const std::map<std::string, std::string> &values);

    private:
      /// The neck's event at this step (travel < 0: none; collective, the
      /// same on every rank), and the thickness of every column this rank
      /// owns kept for the next step.
      SplitEvent<dim> find_neck(const SheetMeasures<dim> &sheet,
                                const double              travel,
                                const double              punch_force,
                                const MPI_Comm            comm);

      parameters::Split              prm;
      double                         t0;
      std::array<SplitEvent<dim>, 3> events;
      double                         last_margin = 100;
      double                         last_travel = 0;
      double                         last_force  = 0;
      using Key = typename SheetMeasures<dim>::Key;
      std::map<Key, double> last_thickness; // owned columns, by key
    };
  } // namespace postprocess
} // namespace formsolve
