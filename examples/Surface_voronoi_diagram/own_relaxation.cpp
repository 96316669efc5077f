// One's own relaxation on the diagram's updates: each step moves every site halfway to the
// centroid of its cell (a damped Lloyd step; the diagram moves the point to the surface), and
// updates the diagram instead of building a new one. Prints the energy per step and the time
// per step beside the package's lloyd_relaxation() on the same sites.
//   own_relaxation [MESH] [SITES] [STEPS]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Surface_voronoi::Euclidean_embedding<Mesh> Metric;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::size_t n = argc > 2 ? std::size_t(std::atol(argv[2])) : 200;
  const std::size_t steps = argc > 3 ? std::size_t(std::atol(argv[3])) : 10;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || n < 2)
  {
    std::cerr << "usage: own_relaxation [MESH] [SITES] [STEPS]: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  Metric metric(mesh);
  const auto sites = SV::blue_noise_sites(mesh, n);
  typedef std::chrono::steady_clock Clock;

  const Clock::time_point start = Clock::now();
  CGAL::Surface_voronoi_diagram<Mesh, Metric> vd(mesh, metric, sites);
  const Clock::time_point built = Clock::now();
  std::cout << "energy " << vd.energy();
  for(std::size_t step = 0; step < steps; ++step)
  {
    const auto& centroids = vd.cell_centroids();
    for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
    {
      const auto p = vd.site_point(i);
      vd.move_site(i, CGAL::midpoint(p, centroids[i]));
    }
    vd.update();
    std::cout << " " << vd.energy();
  }
  const Clock::time_point relaxed = Clock::now();
  const double own = std::chrono::duration<double>(relaxed - built).count() / double(steps);
  std::cout << "\none's own step: " << own << " s" << std::endl;

  // the package's Lloyd on the same sites: one step is the difference of steps + 1 and 1
  auto lloyd = [&](std::size_t k) {
    const Clock::time_point t = Clock::now();
    SV::lloyd_relaxation(mesh, metric, sites, CGAL::parameters::number_of_iterations(k));
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  const double package = (lloyd(steps + 1) - lloyd(1)) / double(steps);
  std::cout << "lloyd_relaxation() step: " << package << " s (the first diagram: "
            << std::chrono::duration<double>(built - start).count() << " s)" << std::endl;
  return EXIT_SUCCESS;
}
