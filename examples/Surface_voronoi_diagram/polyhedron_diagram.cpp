// A diagram on a Polyhedron_3, written into another Polyhedron_3: the package works on any
// FaceGraph. Polyhedron_3 has no internal indices unless its items have ids; the diagram
// makes its own (dynamic property maps), and the output's face -> site map is an
// associative property map.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <boost/property_map/property_map.hpp>

#include <iostream>
#include <map>
#include <set>

typedef CGAL::Epick K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;
namespace SV = CGAL::Surface_voronoi;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : "data/lampshade_thin.off";
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "polyhedron_diagram: cannot read a triangle mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  const auto sites = SV::blue_noise_sites(mesh, 100, CGAL::parameters::random_seed(3));
  CGAL::Biharmonic_embedding<Polyhedron> metric(mesh);
  const CGAL::Surface_voronoi_diagram<Polyhedron> diagram(mesh, metric, sites);

  Polyhedron out;
  std::map<face_descriptor, int> site_of_face;
  SV::make_arrangement(diagram, out, CGAL::parameters::face_patch_map(boost::make_assoc_property_map(site_of_face)));
  std::set<int> labels;
  for(face_descriptor f : faces(out)) labels.insert(site_of_face[f]);
  std::cout << diagram.number_of_sites() << " sites, " << labels.size() << " labels on " << num_faces(out)
            << " arrangement faces, valid: " << std::boolalpha << CGAL::is_valid_polygon_mesh(out) << std::endl;
  return CGAL::is_valid_polygon_mesh(out) ? EXIT_SUCCESS : EXIT_FAILURE;
}
