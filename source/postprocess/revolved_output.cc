#include <deal.II/base/data_out_base.h>

#include <formsolve/postprocess/atomic_output.h>
#include <formsolve/postprocess/revolved_output.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace formsolve
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      using Range =
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>;

      class Revolved : public DataOutInterface<3, 3>
      {
      public:
        std::vector<DataOutBase::Patch<3, 3>> patches;
        std::vector<std::string>              names;
        std::vector<Range>                    ranges;

      protected:
        const std::vector<DataOutBase::Patch<3, 3>> &
        get_patches() const override
        {
          return patches;
        }
        std::vector<std::string> get_dataset_names() const override
        {
          return names;
        }
        std::vector<Range> get_nonscalar_data_ranges() const override
        {
          return ranges;
        }
      };

      /// Section patch @p p swept through segment @p s (of @p step_angle
      /// radians) into @p q, with the fields mapped as write_revolved says.
      void sweep(const DataOutBase::Patch<2, 2>  &p,
                 const unsigned int               s,
                 const double                     step_angle,
                 const std::vector<int>          &vector_start,
                 const std::vector<unsigned int> &target,
                 const unsigned int               n_fields,
                 DataOutBase::Patch<3, 3>        &q)
      {
        q.n_subdivisions = 1;
        q.reference_cell = ReferenceCells::Hexahedron;
        q.data.reinit(n_fields, 8);
        for (unsigned int k = 0; k < 2; ++k)
          {
            // Towards -theta: (r, z, -theta) is right-handed, so the cells
            // have positive volume.
            const double theta = -double(s + k) * step_angle;
            const double co = std::cos(theta), si = std::sin(theta);
            for (unsigned int v = 0; v < 4; ++v)
              {
                const unsigned int w = v + 4 * k;
                const double       r = p.vertices[v][0];
                q.vertices[w] = Point<3>(r * co, r * si, p.vertices[v][1]);
                for (unsigned int c = 0; c < vector_start.size(); ++c)
                  if (vector_start[c] >= 0)
                    {
                      const double vr = p.data(c, v), vz = p.data(c + 1, v);
                      q.data(target[c], w)     = vr * co;
                      q.data(target[c] + 1, w) = vr * si;
                      q.data(target[c] + 2, w) = vz;
                      ++c;
                    }
                  else
                    q.data(target[c], w) = p.data(c, v);
              }
          }
      }
    } // namespace

    std::string write_revolved(const SectionDataOut &section,
                               const double          angle,
                               const std::string    &directory,
                               const unsigned int    step,
                               const MPI_Comm        comm)
    {
      // Map the section's components: a 2-vector (r, z) becomes (x, y, z).
      const auto                names2  = section.get_dataset_names();
      const auto                ranges2 = section.get_nonscalar_data_ranges();
      std::vector<int>          vector_start(names2.size(), -1);
      std::vector<unsigned int> target(names2.size());
      Revolved                  out;
      for (const auto &r : ranges2)
        if (std::get<1>(r) == std::get<0>(r) + 1)
          vector_start[std::get<0>(r)] = std::get<0>(r);
      for (unsigned int c = 0; c < names2.size(); ++c)
        {
          target[c] = out.names.size();
          if (vector_start[c] >= 0)
            {
              for (unsigned int d = 0; d < 3; ++d)
                out.names.push_back(names2[c]);
              out.ranges.emplace_back(
                target[c],
                target[c] + 2,
                names2[c],
                DataComponentInterpretation::component_is_part_of_vector);
              ++c; // the z component belongs to this vector
              target[c] = target[c - 1] + 2;
            }
          else
            out.names.push_back(names2[c]);
        }

      const unsigned int segments =
        std::max(1u, static_cast<unsigned int>(std::ceil(angle / 5.)));
      const double step_angle      = angle / segments * M_PI / 180.;
      const auto  &section_patches = section.get_patches();
      // Pieces of at most about 2 MB of field data, built in place one
      // after the other: fresh memory costs more than writing the file
      // (10 us a page where this was measured, doc/performance.md), and
      // the copy's size stays bounded on fine sections. Every rank writes
      // as many pieces (the record lists them), sized by the largest part.
      const std::size_t bytes_per_segment =
        Utilities::MPI::max(section_patches.size(), comm) * 8 *
        out.names.size() * sizeof(float);
      const unsigned int per_piece =
        std::clamp<std::size_t>((2u << 20) /
                                  std::max<std::size_t>(bytes_per_segment, 1),
                                1,
                                segments);
      const unsigned int n_pieces = (segments + per_piece - 1) / per_piece;
      auto               make     = [&](const unsigned int k) {
        const unsigned int first = k * per_piece,
                           last = std::min(segments, first + per_piece);
        out.patches.resize(section_patches.size() * (last - first));
        auto q = out.patches.begin();
        for (const auto &p : section_patches)
          {
            Assert(p.n_subdivisions == 1 && !p.points_are_available,
                   ExcInternalError());
            for (unsigned int s = first; s < last; ++s, ++q)
              sweep(p,
                    s,
                    step_angle,
                    vector_start,
                    target,
                    out.names.size(),
                    *q);
          }
        for (unsigned int i = 0; i < out.patches.size(); ++i)
          out.patches[i].patch_index = i;
      };
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      out.set_flags(flags);
      return write_vtu_atomically(out,
                                  n_pieces,
                                  make,
                                  directory,
                                  "revolved",
                                  step,
                                  comm);
    }
  } // namespace postprocess
} // namespace formsolve
