// The cells as labels of the input mesh itself: the site of every vertex, and of every face
// a cell covers whole (-1 for the faces a bisector cuts), written into Surface_mesh property
// maps and saved with the mesh as PLY properties (`v:site`, `f:site`).
//   site_maps [MESH] [OUT.ply]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::string out_file = argc > 2 ? argv[2] : "site_maps.ply";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "site_maps: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);
  const CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, SV::blue_noise_sites(mesh, 80, CGAL::parameters::random_seed(4)));

  auto vertex_site = mesh.add_property_map<Mesh::Vertex_index, std::int32_t>("v:site", -1).first;
  auto face_site = mesh.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  SV::compute_vertex_sites(diagram, vertex_site);
  SV::compute_face_sites(diagram, face_site);

  std::size_t whole = 0;
  for(Mesh::Face_index f : mesh.faces()) whole += (face_site[f] >= 0);
  std::cout << mesh.number_of_vertices() << " vertices labelled; " << whole << " of " << mesh.number_of_faces()
            << " faces lie in one cell, the others are cut by a bisector" << std::endl;

  std::ofstream out(out_file, std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  if(!CGAL::IO::write_PLY(out, mesh) || !out.flush())
  {
    std::cerr << "site_maps: cannot write " << out_file << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
