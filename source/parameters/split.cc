#include <deal.II/base/utilities.h>

#include <formsolve/parameters/declared.h>
#include <formsolve/parameters/require.h>
#include <formsolve/parameters/split.h>

namespace formsolve
{
  namespace parameters
  {
    namespace
    {
      const Choice<AfterSplit> after_names{{"stop", AfterSplit::stop},
                                           {"continue", AfterSplit::proceed}};
    } // namespace

    void Split::declare(Declarations &d)
    {
      const Subsection s(d, "Split");
      d.declare(
        "Measures",
        "forming limit, neck, fracture criterion",
        some_of("forming limit|neck|fracture criterion"),
        "Which measures mark the sheet as split (all three are watched and "
        "reported in any case). forming limit: a column's mid-surface "
        "strains reach the forming limit curve (Material/Forming limit "
        "table, or Keeler-Brazier), the crack zone of the FLD. neck: the "
        "thinnest column thins Neck localisation times faster than its "
        "neighbours, at Neck thinning rate or more, while the punch force "
        "falls. fracture criterion: Material/Fracture criterion reaches 1 "
        "by Material/Fracture measure.",
        [this](const std::string &text) {
          by_forming_limit = by_neck = by_fracture = false;
          for (const auto &m : dealii::Utilities::split_string_list(text))
            {
              by_forming_limit |= m == "forming limit";
              by_neck |= m == "neck";
              by_fracture |= m == "fracture criterion";
            }
        });
      d.add("After a split",
            after,
            after_names,
            "stop: end the run Travel past the split after the first split, "
            "so that the results and the report show it; continue: go on to "
            "see how it grows (the run ends as Time stepping/End of run "
            "says, or when the solver fails, which the split then explains).");
      d.add("Travel past the split",
            travel_past,
            number("mm", 0),
            "Punch travel (mm) the run goes on after the first split before "
            "it stops (After a split = stop).");
      d.add("Neck localisation",
            neck_localisation,
            number("-", 1),
            "A neck: the thinnest column's thickness strain grows this many "
            "times faster than the mean of the columns 2 to 5 sheet "
            "thicknesses away from it (-).");
      d.add("Neck thinning rate",
            neck_thinning_rate,
            number("1/mm", 0),
            "A neck: the thinnest column's thickness strain grows at least "
            "this much per mm of punch travel (1/mm), while the punch force "
            "falls.");
    }

    void Split::validate() const
    {
      require(std::isfinite(travel_past),
              "Split/Travel past the split",
              "must be finite");
      require(std::isfinite(neck_localisation) && neck_localisation >= 1,
              "Split/Neck localisation",
              "must be at least 1");
      require(std::isfinite(neck_thinning_rate),
              "Split/Neck thinning rate",
              "must be finite");
    }
  } // namespace parameters
} // namespace formsolve
