// Threads: with CGAL::Parallel_if_available_tag and TBB linked (CGAL_LINKED_WITH_TBB, which
// the package's CMake target defines when it finds TBB), the diagram cuts, stitches and checks
// its cells on the threads TBB allows; tbb::global_control limits them. The diagram is the
// same, bit for bit, as the sequential one: the example compares them.
//   parallel_diagram [MESH] [THREADS]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
typedef CGAL::Biharmonic_embedding<Mesh> Metric;
typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Sequential_diagram;
typedef CGAL::Surface_voronoi_diagram<Mesh, Metric, CGAL::Default, CGAL::Default,
                                      CGAL::Parallel_if_available_tag> Parallel_diagram;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh) || threads < 1)
  {
    std::cerr << "usage: parallel_diagram [MESH] [THREADS >= 1] (a triangle mesh)" << std::endl;
    return EXIT_FAILURE;
  }
#ifdef CGAL_LINKED_WITH_TBB
  // the limit holds while `limit` lives (the library itself changes no global setting)
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::cout << "TBB linked: at most " << threads << " threads" << std::endl;
#else
  std::cout << "TBB not linked: the parallel tag runs on one thread" << std::endl;
#endif
  Metric metric(mesh);
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < 200; ++i)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i * (num_vertices(mesh) / 200))));
  Parallel_diagram parallel(mesh, metric, sites);
  Sequential_diagram sequential(mesh, metric, sites);

  bool same = true;
  for(std::size_t i = 0; i < sites.size(); ++i)
    same = same && parallel.cell_area(i) == sequential.cell_area(i);
  for(Mesh::Vertex_index v : vertices(mesh))
    same = same && parallel.site_of(v) == sequential.site_of(v);
  std::cout << sites.size() << " cells, the same as on one thread: " << (same ? "yes" : "NO") << std::endl;
  return same ? EXIT_SUCCESS : EXIT_FAILURE;
}
