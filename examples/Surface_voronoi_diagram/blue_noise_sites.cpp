// Blue-noise sites (weighted sample elimination) against area-uniform random ones: blue noise
// keeps sites apart, so no two crowd each other and the cells are more even.
//   blue_noise_sites [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Surface_voronoi_diagram<Mesh> Diagram;
namespace SV = CGAL::Surface_voronoi;

// prints the closest pair of sites (straight-line) and the spread of the cell areas
void report(const char* name, const Diagram& d)
{
  double closest = -1, spread = 0;
  const double mean = d.surface_area() / double(d.number_of_sites());
  for(std::size_t i = 0; i < d.number_of_sites(); ++i)
  {
    for(std::size_t j = i + 1; j < d.number_of_sites(); ++j)
    {
      const double s = CGAL::squared_distance(d.site_point(i), d.site_point(j));
      closest = (closest < 0) ? s : (std::min)(closest, s);
    }
    spread += (d.cell_area(i) - mean) * (d.cell_area(i) - mean);
  }
  std::cout << name << ": closest sites " << std::sqrt(closest) << " apart, cell area stddev / mean "
            << std::sqrt(spread / double(d.number_of_sites())) / mean << std::endl;
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
  if(argc > 3)
  {
    std::cerr << "usage: blue_noise_sites [MESH] [SITES]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  char* end = nullptr;
  const long n = argc > 2 ? std::strtol(argv[2], &end, 10) : 300;
  if(argc > 2 && (end == argv[2] || *end != '\0' || n < 2 || n > 100000))
  {
    std::cerr << "blue_noise_sites: SITES must be an integer between 2 and 100000, got '" << argv[2] << "'" << std::endl;
    return EXIT_FAILURE;
  }
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "blue_noise_sites: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    CGAL::Biharmonic_embedding<Mesh> metric(mesh);
    // the same seed gives the same sites on every run and platform
    const Diagram random(mesh, metric, SV::random_sites(mesh, std::size_t(n), CGAL::parameters::random_seed(7)));
    const Diagram blue(mesh, metric, SV::blue_noise_sites(mesh, std::size_t(n), CGAL::parameters::random_seed(7)));
    report("random    ", random);
    report("blue noise", blue);
    if(!write_cells_PLY("random_sites.ply", random) || !write_cells_PLY("blue_noise_sites.ply", blue))
    {
      std::cerr << "blue_noise_sites: cannot write the PLY files" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to random_sites.ply and blue_noise_sites.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "blue_noise_sites: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
