// The README's fifteen lines, compiled: a biharmonic Voronoi diagram of a few vertex sites,
// written as an arrangement with a face -> site map.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>

#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "quick_start: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);   // d = 10, solved once
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < num_vertices(mesh); i += num_vertices(mesh) / 20)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
  CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, sites);
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, int>("f:site", -1).first;
  CGAL::Surface_voronoi::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
  std::cout << sites.size() << " cells, " << num_faces(out) << " arrangement faces" << std::endl;
  return EXIT_SUCCESS;
}
