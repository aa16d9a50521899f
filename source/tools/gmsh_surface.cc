// Tool surfaces through the gmsh library: its meshes, and CAD geometry it
// meshes with OpenCASCADE; and the lines of an axisymmetric tool's profile.
#include <deal.II/base/exceptions.h>

#include <formsolve/app/gmsh_session.h>
#include <formsolve/tools/profile_file.h>
#include <formsolve/tools/surface_file.h>

#include <gmsh.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    namespace
    {
      /// Opens @p file (@p what: "tool surface file" or "tool profile
      /// file") in @p session, meshes geometry at @p facet_size to dimension
      /// @p dim, and reads its node tags and coordinates.
      void open_nodes(const app::GmshSession   &session,
                      const std::string        &what,
                      const std::string        &file,
                      const double              facet_size,
                      const int                 dim,
                      std::vector<std::size_t> &tags,
                      std::vector<double>      &x)
      {
        AssertThrow(std::filesystem::is_regular_file(file),
                    ExcMessage(what + " '" + file + "': no such file"));
        session.checked(what, file, "reading", [&] { gmsh::open(file); });
        if (std::filesystem::path(file).extension() != ".msh")
          session.checked(
            what,
            file,
            dim == 2 ? "meshing the surfaces" : "meshing the curves",
            [&] {
              gmsh::option::setNumber("Mesh.MeshSizeMax", facet_size);
              gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * facet_size);
              gmsh::model::mesh::generate(dim);
            });
        std::vector<double> parametric;
        session.checked(what, file, "reading the nodes", [&] {
          gmsh::model::mesh::getNodes(tags,
                                      x,
                                      parametric,
                                      -1,
                                      -1,
                                      false,
                                      false);
        });
      }

      /// The node tags of the elements of gmsh type @p type (none if the
      /// model has none).
      std::vector<std::size_t> element_nodes(const app::GmshSession &session,
                                             const std::string      &what,
                                             const std::string      &file,
                                             const int               type)
      {
        // gmsh 4.8 leaves the vectors as they were for a type it lacks.
        std::vector<std::size_t> elements, nodes;
        session.checked(what, file, "reading the elements", [&] {
          gmsh::model::mesh::getElementsByType(type, elements, nodes);
        });
        return nodes;
      }
    } // namespace

    SurfaceMesh read_with_gmsh(const std::string &file, const double facet_size)
    {
      const app::GmshSession              session;
      SurfaceMesh                         m;
      std::map<std::size_t, unsigned int> index;
      std::vector<std::size_t>            tags;
      std::vector<double>                 coordinates;
      open_nodes(session,
                 "tool surface file",
                 file,
                 facet_size,
                 2,
                 tags,
                 coordinates);
      for (unsigned int i = 0; i < tags.size(); ++i)
        {
          index[tags[i]] = m.vertices.size();
          m.vertices.emplace_back(coordinates[3 * i],
                                  coordinates[3 * i + 1],
                                  coordinates[3 * i + 2]);
        }
      const auto vertex = [&](const std::size_t tag) {
        const auto it = index.find(tag);
        AssertThrow(it != index.end(),
                    ExcMessage("tool surface file '" + file +
                               "': an element refers to a missing node"));
        return it->second;
      };
      // gmsh element types: 2 triangle, 9 six-node triangle (corners
      // first), 3 quadrilateral, 16 eight-node quadrilateral.
      for (const auto &[type, corners, stride] :
           std::vector<std::array<int, 3>>{{{2, 3, 3}},
                                           {{9, 3, 6}},
                                           {{3, 4, 4}},
                                           {{16, 4, 8}}})
        {
          const auto nodes =
            element_nodes(session, "tool surface file", file, type);
          for (std::size_t e = 0; e + stride <= nodes.size(); e += stride)
            {
              const unsigned int a = vertex(nodes[e]), b = vertex(nodes[e + 1]),
                                 c = vertex(nodes[e + 2]);
              m.triangles.push_back({{a, b, c}});
              if (corners == 4)
                m.triangles.push_back({{a, c, vertex(nodes[e + 3])}});
            }
        }
      AssertThrow(!m.triangles.empty(),
                  ExcMessage("tool surface file '" + file +
                             "': no surface triangles or quadrilaterals in "
                             "it"));
      return m;
    }

    ProfileLines read_profile_with_gmsh(const std::string &file,
                                        const double       facet_size)
    {
      const app::GmshSession   session;
      std::vector<std::size_t> tags;
      std::vector<double>      x;
      open_nodes(session, "tool profile file", file, facet_size, 1, tags, x);
      // The plane the profile is drawn in: y = 0 (x-z) or z = 0 (x-y).
      double span[3] = {0, 0, 0};
      for (std::size_t i = 0; i < tags.size(); ++i)
        for (unsigned int d = 0; d < 3; ++d)
          span[d] = std::max(span[d], std::abs(x[3 * i + d]));
      AssertThrow(span[1] == 0 || span[2] == 0,
                  ExcMessage("tool profile file '" + file +
                             "': the profile must lie in the x-z plane "
                             "(y = 0) or in the x-y plane (z = 0)"));
      const unsigned int                  axial = span[1] == 0 ? 2 : 1;
      ProfileLines                        p;
      std::map<std::size_t, unsigned int> index;
      for (std::size_t i = 0; i < tags.size(); ++i)
        {
          index[tags[i]] = p.points.size();
          p.points.emplace_back(x[3 * i], x[3 * i + axial]);
        }
      // gmsh element types: 1 two-node line, 8 three-node line (ends first).
      for (const auto &[type, stride] :
           std::vector<std::array<int, 2>>{{{1, 2}}, {{8, 3}}})
        {
          const auto nodes =
            element_nodes(session, "tool profile file", file, type);
          for (std::size_t e = 0; e + stride <= nodes.size(); e += stride)
            {
              const auto a = index.find(nodes[e]), b = index.find(nodes[e + 1]);
              AssertThrow(a != index.end() && b != index.end(),
                          ExcMessage("tool profile file '" + file +
                                     "': a line refers to a missing node"));
              p.segments.push_back({{a->second, b->second}});
            }
        }
      AssertThrow(!p.segments.empty(),
                  ExcMessage("tool profile file '" + file +
                             "': no lines in it (the axisymmetric model "
                             "takes the tool's r-z profile as lines)"));
      return p;
    }
  } // namespace tools
} // namespace formsolve
