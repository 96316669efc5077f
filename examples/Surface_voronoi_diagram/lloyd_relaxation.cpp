// Lloyd relaxation: every site moves to the centroid of its cell (projected to the surface)
// and the diagram is computed again. Prints the energy sum_i int_{C_i} |E(x) - E(s_i)|^2 of
// each iteration and writes the diagrams before and after.
//   lloyd_relaxation [MESH] [SITES] [ITERATIONS]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/IO/read_checked_triangle_mesh.h>
#include <CGAL/Surface_voronoi_diagram/IO/write_arrangement_PLY.h>
#include <CGAL/Surface_voronoi_diagram/lloyd.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Surface_voronoi_diagram<Mesh> Diagram;
namespace SV = CGAL::Surface_voronoi;

// a whole-string count in [1, max]: "12abc" and "-3" are refused, not truncated
std::size_t count_argument(const char* text, const char* what, long max)
{
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if(end == text || *end != '\0' || v < 1 || v > max)
    throw SV::Input_error(std::string(what) + " must be an integer between 1 and " + std::to_string(max) + ", got '" + text + "'");
  return std::size_t(v);
}

// the standard deviation of the cell areas over their mean: 0 for equal cells
double area_spread(const Diagram& d)
{
  const double mean = d.surface_area() / double(d.number_of_sites());
  double s = 0;
  for(std::size_t i = 0; i < d.number_of_sites(); ++i) s += (d.cell_area(i) - mean) * (d.cell_area(i) - mean);
  return std::sqrt(s / double(d.number_of_sites())) / mean;
}

int main(int argc, char** argv)
{
  if(argc > 4)
  {
    std::cerr << "usage: lloyd_relaxation [MESH] [SITES] [ITERATIONS]" << std::endl;
    return EXIT_FAILURE;
  }
  try
  {
    const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
    const std::size_t n = argc > 2 ? count_argument(argv[2], "SITES", 100000) : 200;
    const std::size_t iterations = argc > 3 ? count_argument(argv[3], "ITERATIONS", 1000) : 10;
    Mesh mesh;
    SV::IO::read_checked_triangle_mesh(file, mesh);
    CGAL::Biharmonic_embedding<Mesh> metric(mesh);   // computed once for all iterations
    const auto initial = SV::random_sites(mesh, n, 1);
    const SV::Lloyd_result<Mesh> relaxed = SV::lloyd_relaxation(mesh, metric, initial, iterations);

    // the biharmonic energy is reported, not guaranteed to decrease (see the manual)
    for(std::size_t k = 0; k < relaxed.energies.size(); ++k)
      std::cout << "iteration " << k << ": energy " << relaxed.energies[k] << std::endl;
    const Diagram before(mesh, metric, initial), after(mesh, metric, relaxed.sites);
    std::cout << "cell area spread (stddev / mean): " << area_spread(before) << " -> " << area_spread(after)
              << std::endl;
    SV::IO::write_arrangement_PLY("lloyd_before.ply", before);
    SV::IO::write_arrangement_PLY("lloyd_after.ply", after);
    std::cout << "written to lloyd_before.ply and lloyd_after.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "lloyd_relaxation: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
