#include <deal.II/base/exceptions.h>

#include <formsolve/tools/surface_file.h>

#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace formsolve
{
  namespace tools
  {
    using namespace dealii;

    SurfaceMesh read_stl(const std::string &file)
    {
      AssertThrow(std::filesystem::is_regular_file(file),
                  ExcMessage("tool surface file '" + file + "': no such file"));
      std::vector<std::array<double, 3>> points;
      std::vector<std::array<int, 3>>    facets;
      const bool read = CGAL::IO::read_STL(file, points, facets);
      AssertThrow(read,
                  ExcMessage("tool surface file '" + file +
                             "': not a readable STL file (ASCII or binary)"));
      AssertThrow(!facets.empty(),
                  ExcMessage("tool surface file '" + file +
                             "': no triangles in it"));
      SurfaceMesh m;
      for (const auto &p : points)
        m.vertices.emplace_back(p[0], p[1], p[2]);
      for (const auto &f : facets)
        {
          for (const int v : f)
            AssertThrow(v >= 0 && v < static_cast<int>(points.size()),
                        ExcMessage("tool surface file '" + file +
                                   "': a triangle refers to a missing vertex"));
          m.triangles.push_back({{static_cast<unsigned int>(f[0]),
                                  static_cast<unsigned int>(f[1]),
                                  static_cast<unsigned int>(f[2])}});
        }
      return m;
    }

    bool has_area(const SurfaceMesh &m, const std::array<unsigned int, 3> &t)
    {
      const Tensor<1, 3> a = m.vertices[t[1]] - m.vertices[t[0]],
                         b = m.vertices[t[2]] - m.vertices[t[0]];
      return cross_product_3d(a, b).norm() >
             1e-12 * (a.norm_square() + b.norm_square());
    }

    SurfaceMesh read_surface(const std::string &file, const double facet_size)
    {
      std::string extension = std::filesystem::path(file).extension();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      if (extension == ".stl")
        return read_stl(file);
      for (const char *e :
           {".msh", ".geo", ".step", ".stp", ".iges", ".igs", ".brep"})
        if (extension == e)
          return read_with_gmsh(file, facet_size);
      AssertThrow(false,
                  ExcMessage("tool surface file '" + file +
                             "': unknown kind; give an STL (.stl), gmsh "
                             "(.msh, .geo), STEP (.step, .stp), IGES (.iges, "
                             ".igs) or BREP (.brep) file"));
      return {};
    }
  } // namespace tools
} // namespace formsolve
