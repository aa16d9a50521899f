// Triangulated test surfaces (icosphere, open cylinder), an STL writer and
// a check that a call is refused naming a word: shared by the surface tests.
#pragma once

#include <formsolve/tools/surface_file.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <string>

namespace test
{
  using dealii::Point;
  using formsolve::tools::SurfaceMesh;

  /// An icosahedron subdivided @p levels times, on the unit sphere, outward.
  inline SurfaceMesh icosphere(const unsigned int levels)
  {
    const double                t = (1 + std::sqrt(5.)) / 2;
    SurfaceMesh                 m;
    const std::vector<Point<3>> corners = {Point<3>(-1, t, 0),
                                           Point<3>(1, t, 0),
                                           Point<3>(-1, -t, 0),
                                           Point<3>(1, -t, 0),
                                           Point<3>(0, -1, t),
                                           Point<3>(0, 1, t),
                                           Point<3>(0, -1, -t),
                                           Point<3>(0, 1, -t),
                                           Point<3>(t, 0, -1),
                                           Point<3>(t, 0, 1),
                                           Point<3>(-t, 0, -1),
                                           Point<3>(-t, 0, 1)};
    for (const auto &p : corners)
      m.vertices.push_back(p / p.norm());
    for (const auto &f : std::vector<std::array<unsigned int, 3>>{
           {{0, 11, 5}},  {{0, 5, 1}},  {{0, 1, 7}},  {{0, 7, 10}},
           {{0, 10, 11}}, {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}},
           {{10, 7, 6}},  {{7, 1, 8}},  {{3, 9, 4}},  {{3, 4, 2}},
           {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},  {{4, 9, 5}},
           {{2, 4, 11}},  {{6, 2, 10}}, {{8, 6, 7}},  {{9, 8, 1}}})
      m.triangles.push_back(f);
    for (unsigned int l = 0; l < levels; ++l)
      {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> mid;
        auto middle = [&](unsigned int a, unsigned int b) {
          const auto key = std::minmax(a, b);
          const auto it  = mid.find(key);
          if (it != mid.end())
            return it->second;
          const Point<3> p = m.vertices[a] + m.vertices[b];
          m.vertices.push_back(p / p.norm());
          return mid[key] = m.vertices.size() - 1;
        };
        std::vector<std::array<unsigned int, 3>> finer;
        for (const auto &f : m.triangles)
          {
            const unsigned int a = middle(f[0], f[1]), b = middle(f[1], f[2]),
                               c = middle(f[2], f[0]);
            finer.push_back({{f[0], a, c}});
            finer.push_back({{f[1], b, a}});
            finer.push_back({{f[2], c, b}});
            finer.push_back({{a, b, c}});
          }
        m.triangles = finer;
      }
    return m;
  }

  /// An open cylinder of radius 1 about z, 0 <= z <= 2, normals outward.
  inline SurfaceMesh cylinder(const unsigned int n, const unsigned int rows)
  {
    SurfaceMesh m;
    for (unsigned int j = 0; j <= rows; ++j)
      for (unsigned int i = 0; i < n; ++i)
        m.vertices.emplace_back(std::cos(2 * M_PI * i / n),
                                std::sin(2 * M_PI * i / n),
                                2. * j / rows);
    for (unsigned int j = 0; j < rows; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int a = j * n + i, b = j * n + (i + 1) % n, c = a + n,
                             d = b + n;
          m.triangles.push_back({{a, b, d}});
          m.triangles.push_back({{a, d, c}});
        }
    return m;
  }

  inline void
  write_stl(const SurfaceMesh &m, const std::string &file, bool binary)
  {
    std::ofstream f(file, binary ? std::ios::binary : std::ios::out);
    if (!binary)
      f << "solid test\n";
    else
      {
        const std::string header(80, ' ');
        f.write(header.data(), 80);
        const std::uint32_t n = m.triangles.size();
        f.write(reinterpret_cast<const char *>(&n), 4);
      }
    for (const auto &t : m.triangles)
      {
        if (!binary)
          {
            f << "facet normal 0 0 0\nouter loop\n";
            for (const auto v : t)
              f << "vertex " << m.vertices[v][0] << ' ' << m.vertices[v][1]
                << ' ' << m.vertices[v][2] << '\n';
            f << "endloop\nendfacet\n";
          }
        else
          {
            float values[12] = {};
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int d = 0; d < 3; ++d)
                values[3 + 3 * k + d] = m.vertices[t[k]][d];
            f.write(reinterpret_cast<const char *>(values), sizeof(values));
            const std::uint16_t attribute = 0;
            f.write(reinterpret_cast<const char *>(&attribute), 2);
          }
      }
    if (!binary)
      f << "endsolid test\n";
  }

  inline bool refused(const std::function<void()> &f, const std::string &word)
  {
    try
      {
        f();
      }
    catch (const std::exception &e)
      {
        return std::string(e.what()).find(word) != std::string::npos;
      }
    return false;
  }

} // namespace test
