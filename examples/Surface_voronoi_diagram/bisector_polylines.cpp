// The cells' boundaries as polylines, each with the two sites it separates, and the Voronoi
// vertices with the sites around them in counter-clockwise order. The polylines are written
// in the text format of CGAL's demos and of Mesh_3's feature files (one polyline per line:
// the number of points, then their coordinates).
//   bisector_polylines [MESH] [OUT.polylines.txt]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  const std::string out_file = argc > 2 ? argv[2] : "bisectors.polylines.txt";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "bisector_polylines: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  CGAL::Biharmonic_embedding<Mesh> metric(mesh);
  const CGAL::Surface_voronoi_diagram<Mesh> diagram(mesh, metric, SV::blue_noise_sites(mesh, 60, CGAL::parameters::random_seed(2)));

  std::vector<SV::Bisector_polyline<K::Point_3> > polylines;
  std::vector<SV::Voronoi_vertex<K::Point_3> > vertices;
  SV::bisector_polylines(diagram, std::back_inserter(polylines));
  SV::voronoi_vertices(diagram, std::back_inserter(vertices));

  double length = 0;
  std::size_t closed = 0;
  for(const auto& polyline : polylines)
  {
    closed += polyline.is_closed();
    for(std::size_t k = 0; k + 1 < polyline.points.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(polyline.points[k], polyline.points[k + 1]));
  }
  std::cout << polylines.size() << " polylines (" << closed << " closed loops), total length " << length << "; "
            << vertices.size() << " Voronoi vertices" << std::endl;
  if(!polylines.empty())
    std::cout << "the first separates sites " << polylines[0].sites[0] << " and " << polylines[0].sites[1] << " in "
              << polylines[0].points.size() << " points" << std::endl;
  if(!vertices.empty())
  {
    std::cout << "the first Voronoi vertex, at " << vertices[0].point << ", joins the cells of sites";
    for(std::size_t s : vertices[0].sites)
      if(s == diagram.no_site) std::cout << " (border)";
      else std::cout << " " << s;
    std::cout << std::endl;
  }

  std::ofstream out(out_file);
  out.precision(17);
  for(const auto& polyline : polylines)
  {
    out << polyline.points.size();
    for(const K::Point_3& p : polyline.points) out << " " << p;
    out << "\n";
  }
  if(!out.flush())
  {
    std::cerr << "bisector_polylines: cannot write " << out_file << std::endl;
    return EXIT_FAILURE;
  }
  return polylines.empty() ? EXIT_FAILURE : EXIT_SUCCESS;
}
