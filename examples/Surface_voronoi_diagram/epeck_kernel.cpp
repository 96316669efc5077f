// Another kernel: a mesh with CGAL::Epeck points (exact constructions). The diagram computes
// in double whatever the kernel, with exact predicates where a sign decides, and constructs
// the points it returns (site_point(), cell_centroids()) with the mesh's kernel; the cells are
// the same as on the same mesh with Epick points, which the example checks.
//   epeck_kernel [MESH]
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epeck::Point_3> Exact_mesh;
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Exact_mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "epeck_kernel: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<Exact_mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < 50; ++i)
    sites.push_back(Exact_mesh::Vertex_index(Exact_mesh::size_type(i * (num_vertices(mesh) / 50))));
  CGAL::Biharmonic_embedding<Exact_mesh> metric(mesh);
  CGAL::Surface_voronoi_diagram<Exact_mesh> diagram(mesh, metric, sites);
  const CGAL::Epeck::Point_3 centroid = diagram.cell_centroids()[0];   // an Epeck point
  std::cout << "cell 0: centroid " << centroid << ", area " << diagram.cell_area(0) << std::endl;

  // the same file read with Epick points
  Mesh inexact;
  if(!CGAL::IO::read_polygon_mesh(file, inexact) || num_vertices(inexact) != num_vertices(mesh)) return EXIT_FAILURE;
  std::vector<Mesh::Vertex_index> inexact_sites;
  for(Exact_mesh::Vertex_index v : sites) inexact_sites.push_back(Mesh::Vertex_index(Mesh::size_type(v)));
  CGAL::Biharmonic_embedding<Mesh> inexact_metric(inexact);
  CGAL::Surface_voronoi_diagram<Mesh> inexact_diagram(inexact, inexact_metric, inexact_sites);
  bool same = true;
  for(std::size_t v = 0; v < num_vertices(mesh); ++v)
    same = same && diagram.site_of(Exact_mesh::Vertex_index(Exact_mesh::size_type(v)))
                       == inexact_diagram.site_of(Mesh::Vertex_index(Mesh::size_type(v)));
  std::cout << "the same cells as with Epick: " << (same ? "yes" : "NO") << std::endl;
  return same ? EXIT_SUCCESS : EXIT_FAILURE;
}
