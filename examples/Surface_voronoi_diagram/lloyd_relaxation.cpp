// Lloyd relaxation: every site moves to the centroid of its cell (projected to the surface)
// and the diagram is computed again. Prints the energy sum_i int_{C_i} |E(x) - E(s_i)|^2 of
// each iteration and writes the diagrams before and after.
//   lloyd_relaxation [MESH] [SITES] [ITERATIONS]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
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
    throw std::invalid_argument(std::string(what) + " must be an integer between 1 and " + std::to_string(max) + ", got '" + text + "'");
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

// The arrangement as a binary PLY with a site (`f:site`) and a colour (`f:color`) per face.
template <class Diagram>
bool write_cells_PLY(const std::string& file, const Diagram& diagram)
{
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  SV::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  auto color = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(Mesh::Face_index f : out.faces()) color[f] = SV::site_color(site[f]);
  std::ofstream os(file, std::ios::binary);
  CGAL::IO::set_binary_mode(os);
  return CGAL::IO::write_PLY(os, out) && os.flush();
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
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "lloyd_relaxation: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    CGAL::Biharmonic_embedding<Mesh> metric(mesh);   // computed once for all iterations
    const auto initial = SV::random_sites(mesh, n, CGAL::parameters::random_seed(1));
    const SV::Lloyd_result<Mesh> relaxed = SV::lloyd_relaxation(mesh, metric, initial, CGAL::parameters::number_of_iterations(iterations));

    // the biharmonic energy is reported, not guaranteed to decrease (see the manual)
    for(std::size_t k = 0; k < relaxed.energies.size(); ++k)
      std::cout << "iteration " << k << ": energy " << relaxed.energies[k] << std::endl;
    const Diagram before(mesh, metric, initial), after(mesh, metric, relaxed.sites);
    std::cout << "cell area spread (stddev / mean): " << area_spread(before) << " -> " << area_spread(after)
              << std::endl;
    if(!write_cells_PLY("lloyd_before.ply", before) || !write_cells_PLY("lloyd_after.ply", after))
    {
      std::cerr << "lloyd_relaxation: cannot write the PLY files" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to lloyd_before.ply and lloyd_after.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "lloyd_relaxation: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
