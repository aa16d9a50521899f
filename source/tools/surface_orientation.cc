#include <deal.II/base/exceptions.h>

#include <formsolve/tools/surface_orientation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>
#include <vector>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      namespace PMP      = CGAL::Polygon_mesh_processing;
      using SoupKernel   = CGAL::Exact_predicates_inexact_constructions_kernel;
      using SoupMesh     = CGAL::Surface_mesh<SoupKernel::Point_3>;
      using SoupPolygons = std::vector<std::vector<std::size_t>>;
      using SoupPoints   = std::vector<SoupKernel::Point_3>;

      std::string
      edge_text(const SurfaceMesh &m, const std::size_t a, const std::size_t b)
      {
        std::ostringstream s;
        const auto        &p = m.vertices[a], &q = m.vertices[b];
        s << "the edge from (" << p[0] << ", " << p[1] << ", " << p[2]
          << ") to (" << q[0] << ", " << q[1] << ", " << q[2] << ")";
        return s.str();
      }

      /// What CGAL's soup orientation did: the polygons it reversed, and
      /// the first edge of three or more polygons.
      struct Seen
      {
        std::vector<bool>                         reversed;
        std::optional<std::array<std::size_t, 2>> fin;
      };

      /// CGAL copies its visitor: this one writes into a Seen.
      struct Watch : PMP::Default_orientation_visitor
      {
        Seen *seen;
        void  non_manifold_edge(const std::size_t a,
                                const std::size_t b,
                                const std::size_t n_polygons)
        {
          if (!seen->fin && n_polygons > 2)
            seen->fin = std::array<std::size_t, 2>{{a, b}};
        }
        void polygon_orientation_reversed(const std::size_t p)
        {
          seen->reversed[p] = !seen->reversed[p];
        }
      };

      /// Settles the side of one connected part (@p ffg, polygons
      /// @p members of the oriented soup): an open part keeps the file's
      /// majority, a closed one faces outwards.
      template <class Part>
      void settle_part(const Part                     &ffg,
                       const std::vector<std::size_t> &members,
                       SoupPolygons                   &polygons,
                       const std::vector<bool>        &reversed,
                       SurfaceOrientation             &report)
      {
        std::size_t n_turned = 0;
        for (const auto f : members)
          n_turned += reversed[f];
        const bool open = !CGAL::is_closed(ffg);
        bool       turn_all;
        if (open)
          {
            ++report.open_parts;
            turn_all = 2 * n_turned > members.size();
          }
        else
          turn_all = !PMP::is_outward_oriented(ffg);
        if (turn_all)
          {
            for (const auto f : members)
              std::reverse(polygons[f].begin(), polygons[f].end());
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
        ++report.parts;
      }
    } // namespace

    std::string SurfaceOrientation::describe(const std::string &file) const
    {
      std::ostringstream s;
      if (degenerate > 0)
        s << file << ": " << degenerate << " triangles without area left out. ";
      if (joined > 0)
        s << file << ": " << joined
          << " vertices at the position of another joined to it. ";
      if (repeated > 0)
        s << file << ": " << repeated << " triangles given twice left out. ";
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

    SurfaceOrientation orient(SurfaceMesh &m, const std::string &file)
    {
      SurfaceOrientation report;
      const auto         n_before = m.triangles.size();
      m.triangles.erase(std::remove_if(m.triangles.begin(),
                                       m.triangles.end(),
                                       [&](const auto &t) {
                                         return !has_area(m, t);
                                       }),
                        m.triangles.end());
      report.degenerate = n_before - m.triangles.size();
      AssertThrow(!m.triangles.empty(),
                  ExcMessage(file + ": no triangle with an area"));

      // CGAL orients the soup (neighbours agree across every edge); the
      // parts' sides are settled after, on the mesh it makes of the soup.
      SoupPoints points;
      for (const auto &v : m.vertices)
        points.emplace_back(v[0], v[1], v[2]);
      SoupPolygons polygons;
      for (const auto &t : m.triangles)
        polygons.push_back({t[0], t[1], t[2]});
      report.joined =
        PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
      report.repeated =
        PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
      PMP::remove_isolated_points_in_polygon_soup(points, polygons);
      m.vertices.clear();
      for (const auto &p : points)
        m.vertices.emplace_back(p.x(), p.y(), p.z());
      m.triangles.resize(polygons.size());
      Seen seen;
      seen.reversed.assign(polygons.size(), false);
      Watch watch;
      watch.seen = &seen;
      const bool oriented =
        PMP::orient_polygon_soup(points,
                                 polygons,
                                 CGAL::parameters::visitor(watch));
      AssertThrow(!seen.fin,
                  ExcMessage(file + ": three or more triangles share " +
                             edge_text(m, (*seen.fin)[0], (*seen.fin)[1]) +
                             ", so the surface has no two sides there; export "
                             "the tool as one surface"));
      AssertThrow(oriented,
                  ExcMessage(file +
                             ": the surface cannot be oriented (one-sided, "
                             "like a Moebius strip)"));

      SoupMesh mesh;
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      AssertThrow(mesh.number_of_faces() == polygons.size(),
                  ExcInternalError());
      auto part =
        mesh.add_property_map<SoupMesh::Face_index, std::size_t>("f:part")
          .first;
      const std::size_t n_parts = PMP::connected_components(mesh, part);
      std::vector<std::vector<std::size_t>> members(n_parts);
      for (const auto f : mesh.faces())
        members[part[f]].push_back(f.idx());
      for (std::size_t c = 0; c < n_parts; ++c)
        {
          const CGAL::Face_filtered_graph<SoupMesh> ffg(mesh, c, part);
          settle_part(ffg, members[c], polygons, seen.reversed, report);
        }
      for (std::size_t f = 0; f < polygons.size(); ++f)
        for (unsigned int k = 0; k < 3; ++k)
          m.triangles[f][k] = static_cast<unsigned int>(polygons[f][k]);
      return report;
    }
  } // namespace tools
} // namespace formsolve
