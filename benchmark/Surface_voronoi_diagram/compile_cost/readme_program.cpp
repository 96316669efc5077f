// The README's fifteen-line program as it stood at 1719fa1: what a first program costs to compile.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv) {
  Mesh mesh;
  CGAL::IO::read_polygon_mesh(argv[1], mesh);
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);                 // d = 10, solved once
  std::vector<Mesh::Vertex_index> sites = {Mesh::Vertex_index(0), Mesh::Vertex_index(500)};
  CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, sites);
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, int>("f:site", -1).first;
  CGAL::Surface_voronoi::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site));
}
