// The same program with its metric, diagram and arrangement lines replaced by one call of
// Heat_method_3: the yardstick for what a CGAL surface algorithm costs to compile.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv) {
  Mesh mesh;
  CGAL::IO::read_polygon_mesh(argv[1], mesh);
  std::vector<Mesh::Vertex_index> sites = {Mesh::Vertex_index(0), Mesh::Vertex_index(500)};
  auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0).first;
  CGAL::Heat_method_3::estimate_geodesic_distances(mesh, distance, sites);
}
