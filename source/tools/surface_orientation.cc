#include <deal.II/base/exceptions.h>

#include <formsolve/tools/surface_orientation.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      std::string edge_text(const SurfaceMesh &m,
                            const unsigned int a,
                            const unsigned int b)
      {
        std::ostringstream s;
        const auto        &p = m.vertices[a], &q = m.vertices[b];
        s << "the edge from (" << p[0] << ", " << p[1] << ", " << p[2]
          << ") to (" << q[0] << ", " << q[1] << ", " << q[2] << ")";
        return s.str();
      }

      /// Whether triangle @p t runs along its edge from a to b (rather than
      /// from b to a).
      bool runs_forward(const std::array<unsigned int, 3> &t,
                        const unsigned int                 a,
                        const unsigned int                 b)
      {
        for (unsigned int k = 0; k < 3; ++k)
          if (t[k] == a && t[(k + 1) % 3] == b)
            return true;
        return false;
      }

      void turn_over(std::array<unsigned int, 3> &t)
      {
        std::swap(t[1], t[2]);
      }
    } // namespace

    std::string SurfaceOrientation::describe(const std::string &file) const
    {
      std::ostringstream s;
      if (degenerate > 0)
        s << file << ": " << degenerate << " triangles without area left out. ";
      if (turned > 0)
        s << file << ": " << turned
          << " triangles turned to agree with their neighbours. ";
      if (turned_out > 0)
        s << file << ": " << turned_out << " of " << parts - open_parts
          << " closed parts were inside out: turned to face outwards. ";
      std::string text = s.str();
      if (!text.empty())
        text.pop_back();
      return text;
    }

    namespace
    {
      using EdgeMap = std::map<std::pair<unsigned int, unsigned int>,
                               std::vector<unsigned int>>;

      /// Drops the triangles without area (they carry no normal); returns
      /// how many.
      unsigned int drop_degenerate(SurfaceMesh &m)
      {
        const auto n_before = m.triangles.size();
        const auto flat     = [&](const std::array<unsigned int, 3> &t) {
          const Tensor<1, 3> a = m.vertices[t[1]] - m.vertices[t[0]],
                             b = m.vertices[t[2]] - m.vertices[t[0]];
          return !(cross_product_3d(a, b).norm() >
                   1e-12 * (a.norm_square() + b.norm_square()));
        };
        m.triangles.erase(std::remove_if(m.triangles.begin(),
                                         m.triangles.end(),
                                         flat),
                          m.triangles.end());
        return n_before - m.triangles.size();
      }

      /// The triangles at each undirected edge; more than two is an error.
      EdgeMap edges_of(const SurfaceMesh &m, const std::string &file)
      {
        EdgeMap edges;
        for (unsigned int f = 0; f < m.triangles.size(); ++f)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const unsigned int a = m.triangles[f][k],
                                 b = m.triangles[f][(k + 1) % 3];
              auto &faces          = edges[{std::min(a, b), std::max(a, b)}];
              faces.push_back(f);
              AssertThrow(faces.size() <= 2,
                          ExcMessage(file + ": three or more triangles share " +
                                     edge_text(m, a, b) +
                                     ", so the surface has no two sides "
                                     "there; export the tool as one surface"));
            }
        return edges;
      }

      /// One connected part from @p seed, its triangles turned to agree with
      /// the seed (@p turned marks them); whether it has a boundary edge.
      std::vector<unsigned int> walk_part(SurfaceMesh       &m,
                                          const EdgeMap     &edges,
                                          const unsigned int seed,
                                          std::vector<bool> &seen,
                                          std::vector<bool> &turned,
                                          bool              &open,
                                          const std::string &file)
      {
        std::vector<unsigned int> members{seed}, stack{seed};
        seen[seed] = true;
        open       = false;
        while (!stack.empty())
          {
            const unsigned int f = stack.back();
            stack.pop_back();
            for (unsigned int k = 0; k < 3; ++k)
              {
                const unsigned int a = m.triangles[f][k],
                                   b = m.triangles[f][(k + 1) % 3];
                const auto &faces = edges.at({std::min(a, b), std::max(a, b)});
                if (faces.size() == 1)
                  {
                    open = true;
                    continue;
                  }
                const unsigned int g = faces[0] == f ? faces[1] : faces[0];
                // The neighbour must run from b to a.
                const bool agrees = !runs_forward(m.triangles[g], a, b);
                if (seen[g])
                  {
                    AssertThrow(agrees,
                                ExcMessage(file +
                                           ": the surface cannot be oriented "
                                           "(one-sided, like a Moebius "
                                           "strip) at " +
                                           edge_text(m, a, b)));
                    continue;
                  }
                seen[g] = true;
                if (!agrees)
                  {
                    turn_over(m.triangles[g]);
                    turned[g] = true;
                  }
                members.push_back(g);
                stack.push_back(g);
              }
          }
        return members;
      }

      /// Settles a walked part's side: an open part keeps the file's
      /// majority, a closed one faces outwards (positive enclosed volume).
      void settle_part(SurfaceMesh                     &m,
                       const std::vector<unsigned int> &members,
                       const std::vector<bool>         &turned,
                       const bool                       open,
                       SurfaceOrientation              &report)
      {
        unsigned int n_turned = 0;
        for (const auto f : members)
          n_turned += turned[f];
        bool turn_all = 2 * n_turned > members.size();
        if (open)
          ++report.open_parts;
        else
          {
            double volume = 0;
            for (const auto f : members)
              {
                const auto &t = m.triangles[f];
                volume += m.vertices[t[0]] *
                          cross_product_3d(Tensor<1, 3>(m.vertices[t[1]]),
                                           Tensor<1, 3>(m.vertices[t[2]]));
              }
            turn_all = volume < 0;
          }
        if (turn_all)
          {
            for (const auto f : members)
              turn_over(m.triangles[f]);
            n_turned = members.size() - n_turned;
          }
        // A closed part whose majority was turned was inside out; the rest
        // disagreed with their neighbours.
        if (2 * n_turned > members.size())
          {
            ++report.turned_out;
            report.turned += members.size() - n_turned;
          }
        else
          report.turned += n_turned;
      }
    } // namespace

    SurfaceOrientation orient(SurfaceMesh &m, const std::string &file)
    {
      SurfaceOrientation report;
      report.degenerate = drop_degenerate(m);
      AssertThrow(!m.triangles.empty(),
                  ExcMessage(file + ": no triangle with an area"));
      const EdgeMap     edges = edges_of(m, file);
      const std::size_t n     = m.triangles.size();
      std::vector<bool> seen(n, false), turned(n, false);
      for (unsigned int seed = 0; seed < n; ++seed)
        if (!seen[seed])
          {
            bool       open = false;
            const auto members =
              walk_part(m, edges, seed, seen, turned, open, file);
            ++report.parts;
            settle_part(m, members, turned, open, report);
          }
      return report;
    }
  } // namespace tools
} // namespace formsolve
