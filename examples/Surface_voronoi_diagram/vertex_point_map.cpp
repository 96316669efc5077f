// Geometry through a vertex point map: the diagram of a mesh whose vertices are moved by a
// property map (here: the mesh scaled by 2 and lifted, without touching the mesh's points).
// Every function of the package takes the named parameter vertex_point_map; the diagram and
// the metric must be given the same one.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <iostream>

typedef CGAL::Epick K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "vertex_point_map: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  auto moved = mesh.add_property_map<Mesh::Vertex_index, Point>("v:moved").first;
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    moved[v] = Point(2 * p.x(), 2 * p.y(), 2 * p.z() + 1);
  }
  typedef decltype(moved) Moved_map;
  const auto sites = SV::random_sites(mesh, 50, CGAL::parameters::random_seed(2).vertex_point_map(moved));
  CGAL::Biharmonic_embedding<Mesh, Moved_map> metric(mesh, CGAL::parameters::vertex_point_map(moved));
  const CGAL::Surface_voronoi_diagram<Mesh, CGAL::Biharmonic_embedding<Mesh, Moved_map>, Moved_map> diagram(
      mesh, metric, sites, CGAL::parameters::vertex_point_map(moved));
  // the areas are those of the moved mesh: four times the original's
  std::cout << "surface area " << diagram.surface_area() << ", site 0 at " << diagram.site_point(0) << std::endl;
  return EXIT_SUCCESS;
}
