// Tests of CGAL/Surface_voronoi_diagram/arrangement.h: the output works with Surface_mesh and
// Polyhedron_3, is a valid polygon mesh, and generic graph algorithms run on it.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>
#include <CGAL/boost/graph/Dual.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/dijkstra_shortest_paths.h>
#include <CGAL/boost/graph/graph_traits_Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <boost/graph/connected_components.hpp>
#include <boost/graph/filtered_graph.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <map>
#include <unordered_map>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_arrangement {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

// Dual edges that stay inside one cell, for boost::filtered_graph.
template <class G, class SiteMap>
struct Same_cell
{
  const G* g = nullptr;
  SiteMap site;
  Same_cell() {}
  Same_cell(const G& graph, SiteMap s) : g(&graph), site(s) {}
  template <class Edge>
  bool operator()(const Edge& e) const
  {
    const auto h = halfedge(e, *g);
    if(is_border_edge(h, *g)) return false;
    return get(site, face(h, *g)) == get(site, face(opposite(h, *g), *g));
  }
};

} // namespace

TEST_CASE("arrangement: Surface_mesh and Polyhedron_3 inputs and outputs agree", "[arrangement]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 50, 18);
  Polyhedron p;
  CGAL::copy_face_graph(m, p);
  CGAL::set_halfedgeds_items_id(p);

  std::vector<Point> sites;
  for(const auto& l : area_uniform_locations(m, 80, 4)) sites.push_back(point_of(l, m));
  CGAL::Biharmonic_embedding<Mesh> em(m);
  CGAL::Biharmonic_embedding<Polyhedron> ep(p);
  CGAL::Surface_voronoi_diagram<Mesh> dm(m, em, sites);
  CGAL::Surface_voronoi_diagram<Polyhedron> dp(p, ep, sites);
  check_invariants(dm);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(dp.cell_area(i) == Approx(dm.cell_area(i)).epsilon(1e-6));

  // outputs of both kinds, from both diagrams
  Mesh out_m;
  auto site_m = out_m.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  auto bis_m = out_m.add_property_map<Mesh::Edge_index, bool>("e:bisector", false).first;
  auto vv_m = out_m.add_property_map<Mesh::Vertex_index, bool>("v:voronoi", false).first;
  auto in_m = out_m.add_property_map<Mesh::Face_index, Polyhedron::Face_handle>("f:input").first;
  SV::make_arrangement(dp, out_m,
                       SV::parameters::input_face_map(in_m).face_patch_map(site_m).edge_is_constrained_map(bis_m)
                         .vertex_is_constrained_map(vv_m));
  Polyhedron out_p;
  std::unordered_map<Polyhedron::Face_handle, int> site_p;
  SV::make_arrangement(dm, out_p, CGAL::parameters::face_patch_map(boost::make_assoc_property_map(site_p)));
  CHECK(CGAL::is_valid_polygon_mesh(out_m));
  CHECK(CGAL::is_valid_polygon_mesh(out_p));
  CHECK(CGAL::is_closed(out_m));
  CHECK(CGAL::is_closed(out_p));
  CHECK(num_faces(out_m) == num_faces(out_p));
  CHECK(num_vertices(out_m) == num_vertices(out_p));

  // per-cell areas from the outputs equal the diagram's
  // (faces are convex polygons: PMP::face_area only handles triangles)
  auto polygon_area = [](const auto& g, auto f) {
    auto vpm = get(CGAL::vertex_point, g);
    std::vector<Point> p;
    for(auto v : vertices_around_face(halfedge(f, g), g)) p.push_back(get(vpm, v));
    double a = 0;
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      a += std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[k], p[k + 1])));
    return a;
  };
  std::vector<double> area_m(sites.size(), 0.), area_p(sites.size(), 0.);
  for(auto f : faces(out_m)) area_m[std::size_t(site_m[f])] += polygon_area(out_m, f);
  for(auto f : faces(out_p)) area_p[std::size_t(site_p[f])] += polygon_area(out_p, f);
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    CHECK(area_m[i] == Approx(dp.cell_area(i)).epsilon(1e-9));
    CHECK(area_p[i] == Approx(dm.cell_area(i)).epsilon(1e-9));
  }

  // each output face lies in the input face the map names: its centroid is on that triangle
  std::size_t inside = 0, total = 0;
  for(auto f : faces(out_m))
  {
    K::Vector_3 c(0, 0, 0);
    int n = 0;
    for(auto v : vertices_around_face(halfedge(f, out_m), out_m)) { c = c + (out_m.point(v) - CGAL::ORIGIN); ++n; }
    const Point centroid = CGAL::ORIGIN + c / n;
    const auto h = in_m[f]->halfedge();
    const K::Triangle_3 t(h->vertex()->point(), h->next()->vertex()->point(), h->next()->next()->vertex()->point());
    inside += (CGAL::to_double(CGAL::squared_distance(t, centroid)) < 1e-20);
    ++total;
  }
  CHECK(inside == total);

  // bisector edges separate different sites
  std::size_t bisectors = 0;
  for(auto e : edges(out_m))
  {
    const auto h = halfedge(e, out_m);
    const bool differ = site_m[face(h, out_m)] != site_m[face(opposite(h, out_m), out_m)];
    CHECK(bis_m[e] == differ);
    bisectors += differ;
  }
  CHECK(bisectors > 0);
  std::size_t voronoi_vertices = 0;
  for(auto v : vertices(out_m)) voronoi_vertices += vv_m[v];
  CHECK(voronoi_vertices > sites.size());
}

// The indexed copy numbers a compact Surface_mesh by its own indices and stores nothing; a mesh
// with removed elements (not collected) is numbered through stored maps. Both must give the
// diagram of the compacted mesh.
TEST_CASE("arrangement: a Surface_mesh with removed elements gives the diagram of its compacted copy", "[arrangement]")
{
  Mesh compact;
  GEN::make_torus(compact, 1.0, 0.35, 30, 12);
  // the same torus after a removed vertex, face and edge at the front of each range
  Mesh holey;
  const Mesh::Vertex_index v0 = holey.add_vertex(Point(9, 9, 9)), v1 = holey.add_vertex(Point(9, 9, 10)),
                           v2 = holey.add_vertex(Point(9, 10, 9));
  const Mesh::Face_index f0 = holey.add_face(v0, v1, v2);
  REQUIRE(f0 != Mesh::null_face());
  CGAL::copy_face_graph(compact, holey);
  std::vector<Mesh::Edge_index> e0;
  for(auto h : CGAL::halfedges_around_face(halfedge(f0, holey), holey)) e0.push_back(edge(h, holey));
  holey.remove_face(f0);
  for(auto e : e0) holey.remove_edge(e);
  for(auto v : { v0, v1, v2 }) holey.remove_vertex(v);
  REQUIRE(holey.has_garbage());
  // (BGL's num_faces() of a Surface_mesh counts the removed ones too)
  REQUIRE(holey.number_of_faces() == compact.number_of_faces());
  REQUIRE(holey.number_of_vertices() == compact.number_of_vertices());

  SV::internal::Indexed_mesh<Mesh> ic(compact, get(CGAL::vertex_point, compact)), ih(holey, get(CGAL::vertex_point, holey));
  CHECK(ic.vertex_handles.is_identity());
  CHECK(ic.face_handles.is_identity());
  CHECK_FALSE(ih.vertex_handles.is_identity());
  CHECK_FALSE(ih.face_handles.is_identity());
  REQUIRE(ih.number_of_vertices() == holey.number_of_vertices());
  REQUIRE(ih.number_of_faces() == holey.number_of_faces());
  for(std::size_t i = 0; i < ih.number_of_vertices(); ++i)
  {
    CHECK(get(ih.vertex_index, ih.vertex_handles[i]) == i);
    CHECK(get(ic.vertex_index, ic.vertex_handles[i]) == i);
    CHECK_FALSE(holey.is_removed(ih.vertex_handles[i]));
  }
  for(std::size_t i = 0; i < ih.number_of_faces(); ++i)
  {
    CHECK(get(ih.face_index, ih.face_handles[i]) == i);
    CHECK(get(ic.face_index, ic.face_handles[i]) == i);
    CHECK_FALSE(holey.is_removed(ih.face_handles[i]));
  }

  std::vector<Point> sites;
  for(const auto& l : area_uniform_locations(compact, 40, 2)) sites.push_back(point_of(l, compact));
  SV::Euclidean_embedding<Mesh> ec(compact), eh(holey);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > dc(compact, ec, sites), dh(holey, eh, sites);
  check_invariants(dc);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(dh.cell_area(i) == Approx(dc.cell_area(i)).epsilon(1e-12));
  // the same owner at each vertex (copy_face_graph may list the vertices in another order)
  std::map<Point, std::size_t> owners_c, owners_h;
  for(auto v : vertices(compact)) owners_c[compact.point(v)] = dc.site_of(v);
  for(auto v : vertices(holey)) owners_h[holey.point(v)] = dh.site_of(v);
  CHECK(owners_c.size() == compact.number_of_vertices());
  CHECK(owners_c == owners_h);
}

TEST_CASE("arrangement: Boost.Graph connected_components and dijkstra run on it", "[arrangement][bgl]")
{
  Mesh m;
  GEN::make_icosphere(m, 4, 1.0);
  const auto sites = area_uniform_locations(m, 60, 2);
  CGAL::Biharmonic_embedding<Mesh> e(m);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, sites);
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int32_t>("f:site", -1).first;
  auto vv = out.add_property_map<Mesh::Vertex_index, bool>("v:voronoi", false).first;
  SV::make_arrangement(vd, out, CGAL::parameters::face_patch_map(site).vertex_is_constrained_map(vv));

  // Euler: disk cells with degree-3 Voronoi vertices on a sphere give 2 (n - 2) vertices
  std::size_t voronoi_vertices = 0;
  for(auto v : vertices(out)) voronoi_vertices += vv[v];
  CHECK(voronoi_vertices == 2 * (sites.size() - 2));

  // one connected region per cell, counted by Boost on the dual graph without bisector edges
  typedef CGAL::Dual<Mesh> Dual;
  typedef Same_cell<Mesh, decltype(site)> Filter;
  Dual dual(out);
  boost::filtered_graph<Dual, Filter> cells(dual, Filter(out, site));
  auto component = out.add_property_map<Mesh::Face_index, int>("f:cc", -1).first;
  const int regions = boost::connected_components(cells, component);
  CHECK(regions == int(sites.size()));

  // Dijkstra along the refined mesh from a site's vertex: distances are finite everywhere
  // (a closed connected surface) and at least the straight-line distance
  auto vpm = get(CGAL::vertex_point, out);
  auto length = boost::make_function_property_map<Mesh::Edge_index>([&](Mesh::Edge_index ed) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(ed, out)), get(vpm, target(ed, out)))));
  });
  auto dist = out.add_property_map<Mesh::Vertex_index, double>("v:dist", 0.).first;
  const Mesh::Vertex_index src = *vertices(out).begin();
  boost::dijkstra_shortest_paths(out, src, boost::distance_map(dist).weight_map(length));
  double max_d = 0;
  bool lower_bounded = true;
  for(auto v : vertices(out))
  {
    max_d = (std::max)(max_d, dist[v]);
    lower_bounded &= dist[v] + 1e-12 >= std::sqrt(CGAL::to_double(CGAL::squared_distance(out.point(v), out.point(src))));
  }
  CHECK(lower_bounded);
  CHECK(max_d < 4.0);    // half a great circle is pi; edge paths are longer but bounded
  CHECK(max_d > 3.1);

  // the same on a Polyhedron_3 output with ids
  Polyhedron p;
  SV::make_arrangement(vd, p);
  CGAL::set_halfedgeds_items_id(p);
  std::vector<double> d(num_vertices(p));
  auto plength = boost::make_function_property_map<Polyhedron::Halfedge_handle>(
    [](Polyhedron::Halfedge_handle h) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(h->vertex()->point(), h->opposite()->vertex()->point()))); });
  (void)plength;
  auto elen = boost::make_function_property_map<boost::graph_traits<Polyhedron>::edge_descriptor>(
    [&](boost::graph_traits<Polyhedron>::edge_descriptor ed) {
      const auto h = halfedge(ed, p);
      return std::sqrt(CGAL::to_double(CGAL::squared_distance(h->vertex()->point(), h->opposite()->vertex()->point())));
    });
  boost::dijkstra_shortest_paths(p, *vertices(p).begin(),
                                 boost::distance_map(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, p)))
                                   .weight_map(elen));
  CHECK(*std::max_element(d.begin(), d.end()) == Approx(max_d).epsilon(1e-9));
}

TEST_CASE("arrangement: a Polyhedron_3 without ids, as input and as output", "[arrangement]")
{
  typedef CGAL::Polyhedron_3<K> Plain;
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  Plain p;
  CGAL::copy_face_graph(m, p);
  const auto sites_m = area_uniform_locations(m, 40, 9);
  std::vector<Point> sites;
  for(const auto& l : sites_m) sites.push_back(point_of(l, m));
  SV::Euclidean_embedding<Plain> ep(p);
  SV::Euclidean_embedding<Mesh> em(m);
  CGAL::Surface_voronoi_diagram<Plain, SV::Euclidean_embedding<Plain> > dp(p, ep, sites);
  CGAL::Surface_voronoi_diagram<Mesh, SV::Euclidean_embedding<Mesh> > dm(m, em, sites);
  check_invariants(dm);
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    CHECK(dp.cell_area(i) == Approx(dm.cell_area(i)).epsilon(1e-9));
    CHECK(dp.number_of_pieces(i) == 1);
  }
  Plain out;
  std::map<Plain::Face_handle, int> site;
  SV::make_arrangement(dp, out, CGAL::parameters::face_patch_map(boost::make_assoc_property_map(site)));
  CHECK(CGAL::is_valid_polygon_mesh(out));
  CHECK(CGAL::is_closed(out));
  CHECK(site.size() == num_faces(out));
}

} // namespace svd_test_arrangement
