// Progress reports and cancellation with the `callback` named parameter: a callable
// bool(double) called with the fraction of the work done; returning false stops the
// computation, which returns normally with is_cancelled() set. The embedding reports its
// progress; a first diagram is stopped halfway, a second one runs to the end.
//   progress_callback [MESH]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "progress_callback: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  // prints the progress in steps of 10% (the calls come far more often)
  int shown = -1;
  auto report = [&shown](double done) {
    if(int(10 * done) != shown)
    {
      shown = int(10 * done);
      std::cout << "  " << 10 * shown << "%" << std::endl;
    }
    return true;   // go on
  };
  std::cout << "embedding" << std::endl;
  CGAL::Biharmonic_embedding<Mesh> metric(mesh, CGAL::parameters::callback(report));
  if(metric.is_cancelled()) return EXIT_FAILURE;

  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 0; i < 100; ++i)
    sites.push_back(Mesh::Vertex_index(Mesh::size_type(i * (num_vertices(mesh) / 100))));

  // a user pressing "cancel" halfway: the callback says no once half of the work is done
  std::cout << "diagram, cancelled halfway" << std::endl;
  shown = -1;
  CGAL::Surface_voronoi_diagram<Mesh> stopped(mesh, metric, sites,
      CGAL::parameters::callback([&](double done) { return report(done) && done < 0.5; }));
  std::cout << "cancelled: " << std::boolalpha << stopped.is_cancelled() << std::endl;

  std::cout << "diagram" << std::endl;
  shown = -1;
  CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, sites, CGAL::parameters::callback(report));
  std::cout << "cancelled: " << diagram.is_cancelled() << ", area of cell 0: " << diagram.cell_area(0) << std::endl;
  return stopped.is_cancelled() && !diagram.is_cancelled() ? EXIT_SUCCESS : EXIT_FAILURE;
}
