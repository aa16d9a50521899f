#include <deal.II/base/mpi.h>

#include <formsolve/model/dimensions.h>
#include <formsolve/model/position_order.h>
#include <formsolve/postprocess/split_watch.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    std::string split_measure_name(const SplitMeasure m)
    {
      switch (m)
        {
          case SplitMeasure::forming_limit:
            return "forming limit";
          case SplitMeasure::neck:
            return "neck";
          case SplitMeasure::fracture:
            return "fracture criterion";
        }
      return "";
    }

    template <int dim>
    std::string SplitEvent<dim>::where(const model::Model m) const
    {
      const auto         names = model::coordinate_names(m);
      std::ostringstream now;
      now.precision(4);
      for (unsigned int d = 0; d < dim; ++d)
        now << (d > 0 ? ", " : "") << names[d] << " = " << location[d];
      now << " mm";
      // A point whose reference position is not known: where it is now.
      if (std::isnan(reference_radius))
        return now.str();
      std::ostringstream s;
      s.precision(4);
      s << (m == model::Model::plane_strain ? "X0 = " : "R0 = ")
        << reference_radius << " mm";
      if (dim == 3)
        s << ", " << reference_angle << " degrees from x";
      s << " (now " << now.str() << ")";
      return s.str();
    }

    template <int dim>
    SplitWatch<dim>::SplitWatch(const parameters::Split &split,
                                const double             thickness)
        : prm(split)
        , t0(thickness)
    {}

    template <int dim>
    bool SplitWatch<dim>::marks_split(const SplitMeasure m) const
    {
      return m == SplitMeasure::forming_limit ? prm.by_forming_limit
             : m == SplitMeasure::neck        ? prm.by_neck
                                              : prm.by_fracture;
    }

    template <int dim>
    SplitMeasure SplitWatch<dim>::split_measure() const
    {
      // The earliest in punch travel; in a tie, the first listed.
      SplitMeasure best = SplitMeasure::forming_limit;
      double       at   = std::numeric_limits<double>::infinity();
      for (unsigned int m = 0; m < events.size(); ++m)
        if (events[m].met() && marks_split(SplitMeasure(m)) &&
            events[m].travel < at)
          at = events[m].travel, best = SplitMeasure(m);
      return best;
    }

    template <int dim>
    bool SplitWatch<dim>::split() const
    {
      for (unsigned int m = 0; m < events.size(); ++m)
        if (events[m].met() && marks_split(SplitMeasure(m)))
          return true;
      return false;
    }

    template <int dim>
    const SplitEvent<dim> &SplitWatch<dim>::first() const
    {
      return event(split_measure());
    }

    template <int dim>
    std::vector<SplitMeasure>
    SplitWatch<dim>::observe(const SheetMeasures<dim> &sheet,
                             const double              travel,
                             const double              punch_force,
                             const SplitEvent<dim>    &fracture,
                             const MPI_Comm            comm)
    {
      std::vector<SplitMeasure> found;
      auto                     &flc    = events[0];
      const auto               &s      = sheet.summary();
      const double              margin = s.flc_margin;
      if (!flc.met() && margin < 0)
        {
          // Linear in the punch travel between the two steps.
          const double w =
            last_margin > 0 ? last_margin / (last_margin - margin) : 1.;
          flc.travel           = last_travel + w * (travel - last_travel);
          flc.reference_radius = s.flc_radius;
          flc.reference_angle  = s.flc_angle;
          flc.location         = s.flc_location;
          flc.value            = 1 - margin / 100;
          found.push_back(SplitMeasure::forming_limit);
        }

      // Every rank judges the neck alike, from the columns of all.
      const SplitEvent<dim> neck = find_neck(sheet, travel, punch_force, comm);
      if (!events[1].met() && neck.met())
        {
          events[1] = neck;
          found.push_back(SplitMeasure::neck);
        }

      if (!events[2].met() && fracture.met())
        {
          events[2] = fracture;
          found.push_back(SplitMeasure::fracture);
        }
      last_margin = margin;
      last_travel = travel;
      last_force  = punch_force;
      return found;
    }

    template <int dim>
    SplitEvent<dim> SplitWatch<dim>::find_neck(const SheetMeasures<dim> &sheet,
                                               const double              travel,
                                               const double   punch_force,
                                               const MPI_Comm comm)
    {
      namespace mpi    = Utilities::MPI;
      const auto &cols = sheet.columns();
      const auto &keys = sheet.column_keys();
      // The thinnest column that no two tools squeeze (an ironed wall thins
      // where the tools make it); of ties the first in the canonical order.
      // It carries its thickness strain increment of the step (NaN: its
      // thickness a step ago is not known) and its key.
      double least = std::numeric_limits<double>::max();
      for (const auto &c : cols)
        if (!c.squeezed)
          least = std::min(least, c.thickness);
      least = mpi::min(least, comm);
      Candidate<dim> thinnest;
      for (std::size_t c = 0; c < cols.size(); ++c)
        if (!cols[c].squeezed && model::ties(cols[c].thickness, least) &&
            (!thinnest.valid || model::precedes(cols[c].mid, thinnest.point)))
          {
            const auto   before = last_thickness.find(keys[c]);
            const double own    = before == last_thickness.end()
                                    ? std::numeric_limits<double>::quiet_NaN()
                                    : std::log(before->second / cols[c].thickness);
            thinnest            = {true,
                                   cols[c].mid,
                                   {own,
                                    cols[c].reference_radius,
                                    cols[c].reference_angle}};
            thinnest.values.insert(thinnest.values.end(),
                                   keys[c].begin(),
                                   keys[c].end());
          }
      thinnest = first_in_order(comm, thinnest);

      SplitEvent<dim> neck;
      const double    dtravel = travel - last_travel;
      const double    own     = thinnest.valid ? thinnest.values[0] : 0.;
      if (thinnest.valid && !std::isnan(own) && dtravel > 0 &&
          punch_force < last_force)
        {
          Key at;
          for (unsigned int d = 0; d + 1 < dim; ++d)
            at[d] = static_cast<long long>(thinnest.values[3 + d]);
          // Thickness strain increments of the step, positive thinning, of
          // the columns 2 to 5 thicknesses away.
          double sum = 0, n = 0;
          for (std::size_t c = 0; c < cols.size(); ++c)
            {
              const double d  = SheetMeasures<dim>::distance(keys[c], at);
              const auto   it = last_thickness.find(keys[c]);
              if (d < 2 * t0 || d > 5 * t0 || it == last_thickness.end())
                continue;
              sum += std::log(it->second / cols[c].thickness);
              ++n;
            }
          sum = mpi::sum(sum, comm);
          n   = mpi::sum(n, comm);
          // Neighbours that no longer thin: as localised as it gets.
          const double mean = n > 0 ? sum / n : 0.;
          const double localisation =
            mean > 0 ? own / mean : std::numeric_limits<double>::infinity();
          if (n > 0 && own / dtravel >= prm.neck_thinning_rate &&
              localisation >= prm.neck_localisation)
            {
              neck.travel           = travel;
              neck.reference_radius = thinnest.values[1];
              neck.reference_angle  = thinnest.values[2];
              neck.location         = thinnest.point;
              neck.value            = localisation;
            }
        }
      last_thickness.clear();
      for (std::size_t c = 0; c < cols.size(); ++c)
        last_thickness[keys[c]] = cols[c].thickness;
      return neck;
    }

    template <int dim>
    std::map<std::string, std::string> SplitWatch<dim>::save() const
    {
      std::map<std::string, std::string> v;
      auto                               text = [](const double x) {
        std::ostringstream s;
        s.precision(17);
        s << x;
        return s.str();
      };
      for (unsigned int m = 0; m < events.size(); ++m)
        {
          const auto       &e = events[m];
          const std::string k = "split." + std::to_string(m) + ".";
          v[k + "travel"]     = text(e.travel);
          v[k + "radius"]     = text(e.reference_radius);
          v[k + "angle"]      = text(e.reference_angle);
          v[k + "value"]      = text(e.value);
          for (unsigned int d = 0; d < dim; ++d)
            v[k + "x" + std::to_string(d)] = text(e.location[d]);
        }
      v["split.last_margin"] = text(last_margin);
      v["split.last_travel"] = text(last_travel);
      v["split.last_force"]  = text(last_force);
      return v;
    }

    template <int dim>
    void SplitWatch<dim>::load(const std::map<std::string, std::string> &v)
    {
      // Checkpoints written before the split was watched have none of it.
      if (!v.count("split.last_margin"))
        return;
      for (unsigned int m = 0; m < events.size(); ++m)
        {
          auto             &e = events[m];
          const std::string k = "split." + std::to_string(m) + ".";
          e.travel            = std::stod(v.at(k + "travel"));
          e.reference_radius  = std::stod(v.at(k + "radius"));
          e.reference_angle   = std::stod(v.at(k + "angle"));
          e.value             = std::stod(v.at(k + "value"));
          for (unsigned int d = 0; d < dim; ++d)
            e.location[d] = std::stod(v.at(k + "x" + std::to_string(d)));
        }
      last_margin = std::stod(v.at("split.last_margin"));
      last_travel = std::stod(v.at("split.last_travel"));
      last_force  = std::stod(v.at("split.last_force"));
      // The columns' thicknesses are not kept: the neck is judged again
      // from the second step after the resume.
      last_thickness.clear();
    }

#define INSTANTIATE(dim)           \
  template struct SplitEvent<dim>; \
  template class SplitWatch<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace postprocess
} // namespace formsolve
