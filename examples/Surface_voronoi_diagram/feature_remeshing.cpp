// Remeshing that keeps the creases: the edges where the surface turns by more than an angle
// (CGAL::Polygon_mesh_processing::detect_sharp_edges()) are breaklines; sites are placed
// along them first, evenly (feature_line_sites(), the border too), the others drawn away from
// them and relaxed while the line sites stay; the dual's edges then run along the creases.
//   feature_remeshing [MESH] [SITES] [ANGLE] [OUT.off]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/feature_sites.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 2000;
  const double angle = argc > 3 ? std::strtod(argv[3], nullptr) : 60.;
  const std::string out = argc > 4 ? argv[4] : "feature_remeshed.off";
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "feature_remeshing: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    auto crease = mesh.add_property_map<Mesh::Edge_index, bool>("e:crease", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, angle, crease);
    std::size_t creases = 0;
    for(Mesh::Edge_index e : mesh.edges())
    {
      if(mesh.is_border(e)) crease[e] = false;   // the border is a feature line of its own
      creases += crease[e];
    }

    // n sites in all: those on the creases and the border first, then the others
    const auto on_lines = CGAL::parameters::edge_is_constrained_map(crease);
    std::vector<CGAL::Polygon_mesh_processing::Face_location<Mesh, double> > sites = SV::feature_line_sites(mesh, n, on_lines);
    const std::size_t on_features = sites.size();
    if(on_features >= n)
    {
      std::cerr << "feature_remeshing: the feature lines alone take " << on_features << " sites: ask for more" << std::endl;
      return EXIT_FAILURE;
    }
    for(const auto& l : SV::blue_noise_sites(mesh, n - on_features, SV::parameters::placed_sites(sites, CGAL::parameters::random_seed(1))))
      sites.push_back(l);
    std::cout << creases << " crease edges; " << on_features << " of the " << n << " sites on the creases and the border" << std::endl;

    // the creases stop the cells, and the sites on them stay where they are
    SV::Euclidean_embedding<Mesh> metric(mesh);
    const auto relaxed = SV::lloyd_relaxation(mesh, metric, sites,
                                              SV::parameters::first_moving_site(on_features, on_lines.number_of_iterations(10)));
    CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(mesh, metric, relaxed.sites, on_lines);
    std::vector<CGAL::Epick::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    SV::dual_triangulation(diagram, std::back_inserter(points), std::back_inserter(triangles));
    const SV::Dual_validity validity = SV::validate_dual_triangulation(diagram, points, triangles);
    if(!CGAL::IO::write_polygon_soup(out, points, triangles, CGAL::parameters::stream_precision(17)))
    {
      std::cerr << "feature_remeshing: cannot write " << out << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << triangles.size() << " triangles written to " << out
              << (validity.is_valid() ? " (a valid mesh of genus " + std::to_string(validity.genus) + ")"
                                      : " (not a valid mesh: " + validity.reason() + ")") << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "feature_remeshing: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
