// The arrangement is a halfedge mesh like any other, so Boost.Graph and CGAL's graph
// algorithms run on it. Here: the cells as connected components of the faces (two faces
// connected when they share an edge that is not a bisector), counted with
// PMP::connected_components, and the shortest path along the arrangement's edges between two
// sites' cells with boost::dijkstra_shortest_paths.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
namespace SV = CGAL::Surface_voronoi;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "graph_algorithms: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  SV::Euclidean_embedding<Mesh> metric(mesh);
  const CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > diagram(
      mesh, metric, SV::random_sites(mesh, 60, CGAL::parameters::random_seed(5)));

  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, int>("f:site", -1).first;
  auto bisector = out.add_property_map<Mesh::Edge_index, bool>("e:bisector", false).first;
  SV::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(site).edge_is_constrained_map(bisector));

  // one connected component per cell: bisectors cut the arrangement into the cells
  auto component = out.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  const std::size_t cells = PMP::connected_components(out, component, CGAL::parameters::edge_is_constrained_map(bisector));
  std::cout << cells << " components for " << diagram.number_of_sites() << " sites" << std::endl;

  // Dijkstra along the arrangement's edges from the first site's vertex
  auto length = [&](Mesh::Edge_index e) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(out.point(source(e, out)), out.point(target(e, out)))));
  };
  auto weight = boost::make_function_property_map<Mesh::Edge_index, double>(length);
  std::vector<double> distance(num_vertices(out));
  auto distance_map = boost::make_iterator_property_map(distance.begin(), get(boost::vertex_index, out));
  const vertex_descriptor start = *vertices(out).begin();
  boost::dijkstra_shortest_paths(out, start, boost::weight_map(weight).distance_map(distance_map));
  double farthest = 0;
  for(double d : distance) if(d < std::numeric_limits<double>::max()) farthest = (std::max)(farthest, d);
  std::cout << "farthest vertex along the arrangement's edges: " << farthest << std::endl;
  return cells == diagram.number_of_sites() ? EXIT_SUCCESS : EXIT_FAILURE;
}
