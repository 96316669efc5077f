// Remeshing by the dual with the geodesic metric: blue-noise sites relaxed by Lloyd steps,
// sites added on copies of the mesh refined for them until the dual is a valid mesh, and the
// final diagram on the mesh refined for all of them (the geodesic metric knows distances at
// vertices only: where sites crowd, as around a thin part, the mesh must follow).
//   geodesic_remeshing [MESH] [SITES] [ITERATIONS] [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/valid_geodesic_dual_sites.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Surface_voronoi::Geodesic_metric<Mesh> Metric;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 500;
  const std::size_t iterations = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 5;
  const std::string out = argc > 4 ? argv[4] : "geodesic_remeshed.off";
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "geodesic_remeshing: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    Metric metric(mesh);
    const auto relaxed = SV::lloyd_relaxation(mesh, metric, SV::blue_noise_sites(mesh, n, CGAL::parameters::random_seed(1)),
                                              CGAL::parameters::number_of_iterations(iterations));
    // the relaxed sites stay where they are; the added ones follow them (as locations of mesh)
    const auto completed = SV::add_sites_for_valid_geodesic_dual(mesh, relaxed.sites);
    std::cout << completed.sites_added << " sites added for a valid dual" << std::endl;

    // the final diagram, on the mesh the function checked: refined by the local site spacing
    Mesh refined;
    const auto refinement = SV::refine_for_sites(mesh, completed.sites, refined, SV::parameters::refinement_local_spacing(true));
    const bool use_refined = refinement.edges_split > 0;
    const Mesh& work = use_refined ? refined : mesh;
    Metric work_metric(work);
    CGAL::Surface_voronoi_diagram<Mesh, Metric> diagram(work, work_metric, use_refined ? refinement.sites : completed.sites);

    std::vector<CGAL::Epick::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    SV::dual_triangulation(diagram, std::back_inserter(points), std::back_inserter(triangles));
    const SV::Dual_validity validity = SV::validate_dual_triangulation(diagram, points, triangles);
    if(!CGAL::IO::write_polygon_soup(out, points, triangles, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "geodesic_remeshing: cannot write " << out << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << triangles.size() << " triangles on " << points.size() << " sites written to " << out
              << (validity.is_valid() ? " (a valid mesh of genus " + std::to_string(validity.genus) + ")"
                                      : " (not a valid mesh: " + validity.reason() + ")") << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "geodesic_remeshing: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
