// Remeshing by the dual (paper 4.7.3): blue-noise sites, Lloyd relaxation, sites added where
// the dual would not be a valid mesh (cells wrapping around thin parts), and the dual
// triangulation of the final diagram, checked and written as OFF.
//   remeshing [MESH] [SITES] [ITERATIONS] [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/valid_dual_sites.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 2000;
  const std::size_t iterations = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 10;
  const std::string out = argc > 4 ? argv[4] : "remeshed.off";
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "remeshing: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    // The Euclidean embedding gives the best remeshing at high site counts (see the
    // benchmark's Table 1); the biharmonic one with d = 10 is too coarse for thousands of sites.
    SV::Euclidean_embedding<Mesh> metric(mesh);
    const auto relaxed = SV::lloyd_relaxation(mesh, metric, SV::blue_noise_sites(mesh, n, CGAL::parameters::random_seed(1)),
                                              CGAL::parameters::number_of_iterations(iterations));
    std::cout << "energy " << relaxed.energies.front() << " -> " << relaxed.energies.back() << std::endl;
    // the relaxed sites stay where they are; the added ones follow them
    const auto completed = SV::add_sites_for_valid_dual(mesh, metric, relaxed.sites);
    std::cout << completed.sites_added << " sites added for a valid dual" << std::endl;
    CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(mesh, metric, completed.sites);
    std::vector<CGAL::Epick::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    SV::dual_triangulation(diagram, std::back_inserter(points), std::back_inserter(triangles));
    const SV::Dual_validity validity = SV::validate_dual_triangulation(diagram, points, triangles);
    if(!CGAL::IO::write_polygon_soup(out, points, triangles, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "remeshing: cannot write " << out << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << triangles.size() << " triangles on " << points.size() << " sites written to " << out
              << (validity.is_valid() ? " (a valid mesh of genus " + std::to_string(validity.genus) + ")"
                                      : " (not a valid mesh: " + validity.reason() + ")") << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "remeshing: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
