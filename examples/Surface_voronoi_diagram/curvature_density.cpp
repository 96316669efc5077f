// Smaller cells where the surface bends: a density of sites from the curvature
// (curvature_density()), read by blue-noise sampling and by Lloyd relaxation through the
// named parameter vertex_density_map. Prints the mean cell area near the most and the least
// curved vertices, with and without the density, and writes the cells with the density.
//   curvature_density [MESH] [SITES]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/curvature_density.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Surface_voronoi::Euclidean_embedding<Mesh> Metric;
typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
namespace SV = CGAL::Surface_voronoi;

// the mean area of the cells owning the given vertices
double mean_cell_area(const Diagram& d, const std::vector<Mesh::Vertex_index>& vs)
{
  double total = 0;
  for(Mesh::Vertex_index v : vs) total += d.cell_area(d.site_of(v));
  return total / double(vs.size());
}

int main(int argc, char** argv)
{
  if(argc > 3)
  {
    std::cerr << "usage: curvature_density [MESH] [SITES]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string file = argc > 1 ? argv[1] : "data/torus.off";
  char* end = nullptr;
  const long n = argc > 2 ? std::strtol(argv[2], &end, 10) : 400;
  if(argc > 2 && (end == argv[2] || *end != '\0' || n < 2 || n > 100000))
  {
    std::cerr << "curvature_density: SITES must be an integer between 2 and 100000, got '" << argv[2] << "'" << std::endl;
    return EXIT_FAILURE;
  }
  try
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.is_empty())
    {
      std::cerr << "curvature_density: cannot read a triangle mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    // up to 8 times as many sites per unit area where the surface bends most
    auto density = mesh.add_property_map<Mesh::Vertex_index, double>("v:density", 1.).first;
    SV::curvature_density(mesh, density, SV::parameters::max_density_ratio(8.));

    Metric metric(mesh);
    const auto plain_sites = SV::lloyd_relaxation(mesh, metric,
        SV::blue_noise_sites(mesh, std::size_t(n), CGAL::parameters::random_seed(7)),
        CGAL::parameters::number_of_iterations(10)).sites;
    const auto dense_sites = SV::lloyd_relaxation(mesh, metric,
        SV::blue_noise_sites(mesh, std::size_t(n), SV::parameters::vertex_density_map(density, CGAL::parameters::random_seed(7))),
        SV::parameters::vertex_density_map(density, CGAL::parameters::number_of_iterations(10))).sites;
    const Diagram plain(mesh, metric, plain_sites), dense(mesh, metric, dense_sites);

    // the tenth of the vertices where the density is highest, and the tenth where it is lowest
    std::vector<Mesh::Vertex_index> order(mesh.vertices().begin(), mesh.vertices().end());
    std::sort(order.begin(), order.end(), [&](Mesh::Vertex_index a, Mesh::Vertex_index b) { return density[a] > density[b]; });
    const std::size_t tenth = (std::max)(std::size_t(1), order.size() / 10);
    const std::vector<Mesh::Vertex_index> curved(order.begin(), order.begin() + tenth), flat(order.end() - tenth, order.end());
    std::cout << "mean cell area, most curved / least curved tenth of the vertices:\n"
              << "  uniform:   " << mean_cell_area(plain, curved) << " / " << mean_cell_area(plain, flat) << "\n"
              << "  curvature: " << mean_cell_area(dense, curved) << " / " << mean_cell_area(dense, flat) << std::endl;

    Mesh out;
    auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
    SV::make_arrangement(dense, out, CGAL::parameters::face_patch_map(site));
    auto color = out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
    for(Mesh::Face_index f : out.faces()) color[f] = SV::site_color(site[f]);
    std::ofstream os("curvature_density.ply", std::ios::binary);
    CGAL::IO::set_binary_mode(os);
    if(!CGAL::IO::write_PLY(os, out) || !os.flush())
    {
      std::cerr << "curvature_density: cannot write curvature_density.ply" << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "written to curvature_density.ply" << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "curvature_density: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
