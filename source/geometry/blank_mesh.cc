#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <formsolve/app/gmsh_session.h>
#include <formsolve/app/rank_zero.h>
#include <formsolve/geometry/blank_mesh.h>
#include <formsolve/model/dimensions.h>

#include <gmsh.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace formsolve
{
  namespace geometry
  {
    using namespace dealii;
    using model::Model;
    using parameters::BlankShape;

    namespace
    {
      /// The text of a 2-D quadrilateral mesh in gmsh's format 2: the file,
      /// or a .geo meshed by the gmsh library (quadrilaterals by
      /// recombination and subdivision).
      std::string planform_text(const std::string &file)
      {
        AssertThrow(std::ifstream(file).good(),
                    ExcMessage("Geometry/Mesh file: cannot open '" + file +
                               "'"));
        const auto ext = std::filesystem::path(file).extension().string();
        AssertThrow(ext == ".geo" || ext == ".msh",
                    ExcMessage("Geometry/Mesh file: '" + file +
                               "' is neither .msh nor .geo"));
        std::ostringstream text;
        if (ext == ".msh")
          {
            text << std::ifstream(file).rdbuf();
            return text.str();
          }
        const auto msh = std::filesystem::temp_directory_path() /
                         ("formsolve-" + std::to_string(::getpid()) + ".msh");
        {
          const app::GmshSession gmsh_session;
          gmsh_session.checked("Geometry/Mesh file:", file, "meshing", [&] {
            gmsh::option::setNumber("Mesh.RecombineAll", 1);
            gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
            gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
            gmsh::open(file);
            gmsh::model::mesh::generate(2);
            gmsh::write(msh.string());
          });
        }
        text << std::ifstream(msh).rdbuf();
        std::filesystem::remove(msh);
        return text.str();
      }

      void read_planform(const std::string &file, Triangulation<2> &planform)
      {
        // Rank 0 meshes (gmsh takes its time), every rank reads the text.
        std::istringstream input(
          app::on_rank_zero<std::string>(MPI_COMM_WORLD,
                                         [&] { return planform_text(file); }));
        GridIn<2> in(planform);
        try
          {
            in.read_msh(input);
          }
        catch (const ExceptionBase &)
          {
            AssertThrow(false,
                        ExcMessage("Geometry/Mesh file: '" + file +
                                   "' is not a 2-D quadrilateral gmsh mesh"));
          }
        AssertThrow(planform.n_active_cells() > 0 &&
                      planform.all_reference_cells_are_hyper_cube(),
                    ExcMessage("Geometry/Mesh file: '" + file +
                               "' must be a 2-D mesh of quadrilaterals only"));
      }

      /// The planform of the modelled part: quarter x, y >= 0; half x >= 0.
      void create_planform(const parameters::Geometry &g, Triangulation<2> &t)
      {
        const double R = 0.5 * g.blank_diameter;
        if (g.blank_shape == BlankShape::round)
          {
            if (g.model == Model::quarter)
              GridGenerator::quarter_hyper_ball(t, Point<2>(), R);
            else if (g.model == Model::half)
              {
                GridGenerator::half_hyper_ball(t, Point<2>(), R);
                // Turn it to x >= 0 (a rotation keeps the cells' orientation).
                double x = 0;
                for (const auto &cell : t.active_cell_iterators())
                  x += cell->center()[0];
                if (x < 0)
                  GridTools::rotate(M_PI, t);
              }
            else
              GridGenerator::hyper_ball(t, Point<2>(), R);
          }
        else if (g.blank_shape == BlankShape::rectangle)
          {
            // The slice is the half x >= 0 over the whole width, y >= 0.
            const bool   slice  = g.model == Model::slice;
            const bool   half_x = model::symmetric_in_x(g.model);
            const bool   half_y = model::symmetric_in_y(g.model);
            const double lx = half_x ? 0.5 * g.blank_length : g.blank_length;
            const double ly =
              half_y && !slice ? 0.5 * g.blank_width : g.blank_width;
            const double                    h    = std::min(lx, ly);
            const std::vector<unsigned int> reps = {
              std::max(1u, static_cast<unsigned int>(std::round(lx / h))),
              std::max(1u, static_cast<unsigned int>(std::round(ly / h)))};
            const Point<2> lo(half_x ? 0. : -lx / 2, half_y ? 0. : -ly / 2);
            GridGenerator::subdivided_hyper_rectangle(t,
                                                      reps,
                                                      lo,
                                                      lo + Point<2>(lx, ly));
          }
        else
          read_planform(g.mesh_file, t);
      }

      /// Manifold id of the rim of a round blank (the cylinder r = R).
      constexpr types::manifold_id rim_manifold = 1;

      /// The rim of a round blank: the cylinder r = R for the refinements
      /// that make the initial mesh, flat beyond. Adaptive refinement must
      /// keep the geometry (the displacement is prolongated exactly only if
      /// a new reference vertex is the midpoint of the old ones; on the
      /// circle it would bulge the drawn rim out and add volume). A new
      /// point goes on the circle only where the points it comes from lie at
      /// least @p min_chord apart in the plane, as the rim edges of the
      /// initial mesh and coarser ones do: every rank decides alike, and a
      /// cell re-created after repartitioning or a restart is the same.
      class RimManifold : public CylindricalManifold<3>
      {
      public:
        explicit RimManifold(const double min_chord)
            : CylindricalManifold<3>(2)
            , min_chord(min_chord)
        {}

        std::unique_ptr<Manifold<3>> clone() const override
        {
          return std::make_unique<RimManifold>(min_chord);
        }

        Point<3>
        get_new_point(const ArrayView<const Point<3>> &points,
                      const ArrayView<const double>   &weights) const override
        {
          double chord = 0;
          for (const auto &a : points)
            for (const auto &b : points)
              chord = std::max(chord, std::hypot(a[0] - b[0], a[1] - b[1]));
          if (chord >= min_chord)
            return CylindricalManifold<3>::get_new_point(points, weights);
          Point<3> p;
          for (unsigned int i = 0; i < points.size(); ++i)
            p += weights[i] * points[i];
          return p;
        }

        void get_new_points(const ArrayView<const Point<3>> &points,
                            const Table<2, double>          &weights,
                            ArrayView<Point<3>> new_points) const override
        {
          std::vector<double> w(weights.size(1));
          for (unsigned int row = 0; row < weights.size(0); ++row)
            {
              for (unsigned int i = 0; i < w.size(); ++i)
                w[i] = weights(row, i);
              new_points[row] = get_new_point(points, make_array_view(w));
            }
        }

      private:
        double min_chord;
      };

      void create_coarse(const parameters::Geometry &g,
                         const parameters::Mesh     &m,
                         Triangulation<3>           &tria)
      {
        const unsigned int k = initial_mesh_level(m);
        Triangulation<2>   planform;
        create_planform(g, planform);
        planform.refine_global(m.refinements - k);

        // Drop the planform's manifolds: refinement in the sheet is flat,
        // except on the rim of a round blank (below).
        Triangulation<2> flat;
        GridGenerator::flatten_triangulation(planform, flat);

        const unsigned int  layers = m.layers >> k;
        std::vector<double> z(layers + 1);
        for (unsigned int j = 0; j <= layers; ++j)
          z[j] = g.thickness * j / layers;
        Triangulation<3> serial;
        GridGenerator::extrude_triangulation(flat, z, serial);
        const double tol = 1e-6 * g.thickness;
        const bool   rim = g.blank_shape == BlankShape::round;
        for (const auto &cell : serial.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const Point<3> c = face->center();
                face->set_boundary_id(boundary_id(g, c));
                if (rim && face->boundary_id() == free_surface &&
                    std::abs(c[2]) > tol && std::abs(c[2] - g.thickness) > tol)
                  face->set_all_manifold_ids(rim_manifold);
              }
        tria.copy_triangulation(serial);
        // The p4est refinements put the rim's new vertices on the circle, as
        // the planform's own refinement did, so the initial mesh is the same
        // as the refined planform extruded. It stays attached: every rank
        // must place the vertices of a cell it re-creates identically.
        // The edges split to make the initial mesh (levels below k) are at
        // least the coarse chord c / 2^(k-1) long, those of the initial
        // mesh at most 1.11 c / 2^k (a quarter circle or less per coarse
        // edge).
        if (rim)
          {
            double chord = std::numeric_limits<double>::max();
            for (const auto &cell : serial.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->manifold_id() == rim_manifold)
                  for (unsigned int l = 0; l < face->n_lines(); ++l)
                    {
                      const auto   a = face->line(l)->vertex(0);
                      const auto   b = face->line(l)->vertex(1);
                      const double c = std::hypot(a[0] - b[0], a[1] - b[1]);
                      if (c > 0)
                        chord = std::min(chord, c);
                    }
            tria.set_manifold(rim_manifold,
                              RimManifold(k == 0
                                            ? std::numeric_limits<double>::max()
                                            : 1.5 * chord / (1u << k)));
          }
      }

      void create_coarse(const parameters::Geometry &g,
                         const parameters::Mesh     &m,
                         Triangulation<2>           &tria)
      {
        Assert(model::space_dimension(g.model) == 2, ExcInternalError());
        const bool         axi = g.model == Model::axisymmetric;
        const unsigned int k   = initial_mesh_level(m);
        // The section's half length: r from the axis, or x from the plane
        // of symmetry.
        const double     R = 0.5 * (axi ? g.blank_diameter : g.blank_length);
        Triangulation<2> serial;
        GridGenerator::subdivided_hyper_rectangle(serial,
                                                  {2u << (m.refinements - k),
                                                   m.layers >> k},
                                                  Point<2>(0, 0),
                                                  Point<2>(R, g.thickness));
        set_boundary_ids(g, serial);
        tria.copy_triangulation(serial);
      }
    } // namespace

    template <int dim>
    types::boundary_id boundary_id(const parameters::Geometry &g,
                                   const Point<dim>           &c)
    {
      const double tol = 1e-6 * g.thickness;
      if constexpr (dim == 2)
        return c[0] >= tol                      ? free_surface
               : g.model == Model::axisymmetric ? axis
                                                : symmetry_x;
      if (std::abs(c[dim - 1]) <= tol ||
          std::abs(c[dim - 1] - g.thickness) <= tol)
        return free_surface;
      if (model::symmetric_in_x(g.model) && std::abs(c[0]) < tol)
        return symmetry_x;
      if (model::symmetric_in_y(g.model) &&
          (std::abs(c[1]) < tol ||
           (g.model == Model::slice && std::abs(c[1] - g.blank_width) < tol)))
        return symmetry_y;
      return free_surface;
    }

    template <int dim>
    void set_boundary_ids(const parameters::Geometry &g, Triangulation<dim> &t)
    {
      for (const auto &cell : t.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(boundary_id(g, face->center()));
    }

    unsigned int initial_mesh_level(const parameters::Mesh &m)
    {
      unsigned int k = 0;
      while (k < m.refinements && m.layers % (2u << k) == 0)
        ++k;
      return k;
    }

    template <int dim>
    void create_coarse_blank_mesh(const parameters::Geometry &g,
                                  const parameters::Mesh     &m,
                                  Triangulation<dim>         &tria)
    {
      AssertThrow(model::space_dimension(g.model) == dim, ExcInternalError());
      create_coarse(g, m, tria);
    }

    template <int dim>
    void create_blank_mesh(const parameters::Geometry                &g,
                           const parameters::Mesh                    &m,
                           parallel::distributed::Triangulation<dim> &tria)
    {
      create_coarse_blank_mesh(g, m, tria);
      tria.refine_global(initial_mesh_level(m));
    }

#define INSTANTIATE(dim)                                                     \
  template void create_blank_mesh<dim>(                                      \
    const parameters::Geometry &,                                            \
    const parameters::Mesh &,                                                \
    parallel::distributed::Triangulation<dim> &);                            \
  template void create_coarse_blank_mesh<dim>(const parameters::Geometry &,  \
                                              const parameters::Mesh &,      \
                                              Triangulation<dim> &);         \
  template types::boundary_id boundary_id(const parameters::Geometry &,      \
                                          const Point<dim> &);               \
  template void               set_boundary_ids(const parameters::Geometry &, \
                                               Triangulation<dim> &);
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace geometry
} // namespace formsolve
