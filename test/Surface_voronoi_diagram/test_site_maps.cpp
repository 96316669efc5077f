// Tests of CGAL/Surface_voronoi_diagram/site_maps.h: the site of every vertex and of every
// face a cell covers whole, into Surface_mesh and associative property maps, checked against
// the diagram's site_of(), against the nearest site by Euclidean distance, and against the
// pieces of the arrangement.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/site_maps.h>
#include <test_meshes.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <map>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_site_maps {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;

// The nearest site by Euclidean distance, or -1 when two sites are nearly as near (a tie the
// diagram breaks its own way).
long nearest_site(const Euclidean_diagram& vd, const Point& p)
{
  double best = std::numeric_limits<double>::infinity(), second = best;
  long site = -1;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
  {
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, vd.site_point(i))));
    if(d < best) { second = best; best = d; site = long(i); }
    else if(d < second) second = d;
  }
  return second - best < 1e-9 ? -1 : site;
}

} // namespace

TEST_CASE("site maps: vertex sites are the diagram's and the nearest sites", "[site_maps]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 4, 1.0);
  Euclidean e(sphere);
  const Euclidean_diagram vd(sphere, e, area_uniform_locations(sphere, 50, 6));
  auto vsite = sphere.add_property_map<Mesh::Vertex_index, int>("v:site", -7).first;
  SV::compute_vertex_sites(vd, vsite);
  std::size_t as_diagram = 0, as_nearest = 0, compared = 0;
  for(Mesh::Vertex_index v : sphere.vertices())
  {
    as_diagram += (vsite[v] == int(vd.site_of(v)));
    const long nearest = nearest_site(vd, sphere.point(v));
    if(nearest < 0) continue;
    ++compared;
    as_nearest += (vsite[v] == nearest);
  }
  CHECK(as_diagram == sphere.number_of_vertices());
  CHECK(compared > sphere.number_of_vertices() - 10);
  CHECK(as_nearest == compared);
  // every site owns some vertex here, and no vertex is left without one
  std::set<int> used;
  for(Mesh::Vertex_index v : sphere.vertices()) used.insert(vsite[v]);
  CHECK(used.size() == vd.number_of_sites());
  CHECK(*used.begin() == 0);
}

TEST_CASE("site maps: a face has a site when its cell covers it whole", "[site_maps]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 60, 24);
  Euclidean e(torus);
  const Euclidean_diagram vd(torus, e, area_uniform_locations(torus, 30, 2));
  auto fsite = torus.add_property_map<Mesh::Face_index, long>("f:site", -7).first;
  SV::compute_face_sites(vd, fsite);

  // the oracle: the arrangement's faces in each input face, with their sites
  Mesh arrangement;
  auto piece_site = arrangement.add_property_map<Mesh::Face_index, long>("f:site", -7).first;
  auto input_face = arrangement.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input").first;
  SV::make_arrangement(vd, arrangement, SV::parameters::input_face_map(input_face).face_patch_map(piece_site));
  std::map<Mesh::Face_index, std::vector<long> > pieces;
  for(Mesh::Face_index f : arrangement.faces()) pieces[input_face[f]].push_back(piece_site[f]);

  std::size_t agree = 0, whole = 0, nearest_agree = 0, nearest_compared = 0;
  for(Mesh::Face_index f : torus.faces())
  {
    const std::vector<long>& p = pieces[f];
    const long expected = p.size() == 1 ? p[0] : -1;
    agree += (fsite[f] == expected);
    whole += (fsite[f] >= 0);
    // Euclidean bisectors are planes: a face whose corners all have one nearest site lies
    // in that site's cell, and a face cut by a bisector has corners of two sites
    std::set<long> corner_sites;
    bool tie = false;
    for(Mesh::Vertex_index v : vertices_around_face(torus.halfedge(f), torus))
    {
      const long s = nearest_site(vd, torus.point(v));
      tie |= (s < 0);
      corner_sites.insert(s);
    }
    if(tie) continue;
    ++nearest_compared;
    nearest_agree += (fsite[f] == (corner_sites.size() == 1 ? *corner_sites.begin() : -1));
  }
  CHECK(agree == torus.number_of_faces());
  CHECK(nearest_agree == nearest_compared);
  CHECK(nearest_compared > torus.number_of_faces() - 20);
  // most faces are whole, some are cut
  CHECK(whole > torus.number_of_faces() / 2);
  CHECK(whole < torus.number_of_faces());
}

TEST_CASE("site maps: a Polyhedron_3 with associative maps, and area no site reaches", "[site_maps]")
{
  // two spheres, sites on the first only: every vertex and face of the second is -1
  Mesh two, second;
  GEN::make_icosphere(two, 3, 1.0);
  GEN::make_icosphere(second, 3, 1.0);
  for(Mesh::Vertex_index v : second.vertices()) second.point(v) = second.point(v) + K::Vector_3(3, 0, 0);
  CGAL::copy_face_graph(second, two);
  typedef CGAL::Polyhedron_3<K> Plain;
  Plain p;
  CGAL::copy_face_graph(two, p);
  std::vector<Point> sites;
  for(const auto& l : area_uniform_locations(two, 100, 1))
  {
    const Point q = point_of(l, two);
    if(q.x() < 1.5 && sites.size() < 12) sites.push_back(q);
  }
  SV::Euclidean_embedding<Plain> e(p);
  const CGAL::Surface_voronoi_diagram<Plain, SV::Euclidean_embedding<Plain> > vd(p, e, sites);
  REQUIRE(vd.unreached_area() > 0);

  std::map<Plain::Vertex_handle, std::size_t> vsite;
  std::map<Plain::Face_handle, int> fsite;
  SV::compute_vertex_sites(vd, boost::make_assoc_property_map(vsite));
  SV::compute_face_sites(vd, boost::make_assoc_property_map(fsite));
  REQUIRE(vsite.size() == num_vertices(p));
  REQUIRE(fsite.size() == num_faces(p));
  std::size_t vertices_right = 0, faces_right = 0;
  for(Plain::Vertex_handle v : vertices(p))
  {
    if(v->point().x() > 1.5) vertices_right += (vsite[v] == std::size_t(-1));
    else vertices_right += (vsite[v] == vd.site_of(v) && vsite[v] < sites.size());
  }
  for(Plain::Face_handle f : faces(p))
  {
    if(f->halfedge()->vertex()->point().x() > 1.5) faces_right += (fsite[f] == -1);
    else faces_right += (fsite[f] >= -1 && fsite[f] < int(sites.size()));
  }
  CHECK(vertices_right == num_vertices(p));
  CHECK(faces_right == num_faces(p));
}

} // namespace svd_test_site_maps
