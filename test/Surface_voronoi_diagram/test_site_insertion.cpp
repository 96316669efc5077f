// Tests of CGAL/Surface_voronoi_diagram/site_insertion.h: the paper's insertion mode.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/site_insertion.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_site_insertion {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

// Inner edges (both faces from the same input face) must be locally Delaunay.
template <class Result>
std::size_t non_delaunay_inner_edges(const Result& r)
{
  const auto& m = r.mesh;
  std::size_t bad = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m), o = opposite(h, m);
    if(is_border(h, m) || is_border(o, m)) continue;
    if(r.input_face[face(h, m)] != r.input_face[face(o, m)]) continue;
    const Point a = m.point(source(h, m)), b = m.point(target(h, m));
    const Point c = m.point(target(next(h, m), m)), d = m.point(target(next(o, m), m));
    // opposite angles sum to at most pi
    const double ac = std::acos(std::max(-1., std::min(1., CGAL::to_double((a - c) * (b - c)) /
                                                              std::sqrt(CGAL::to_double((a - c).squared_length() * (b - c).squared_length())))));
    const double ad = std::acos(std::max(-1., std::min(1., CGAL::to_double((a - d) * (b - d)) /
                                                              std::sqrt(CGAL::to_double((a - d).squared_length() * (b - d).squared_length())))));
    bad += (ac + ad > CGAL_PI + 1e-9);
  }
  return bad;
}

} // namespace

TEST_CASE("insertion: sites become vertices of a valid Delaunay-refined copy", "[insertion]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 30, 12);
  auto sites = area_uniform_locations(m, 200, 6);
  // a site on an edge, a site at a vertex, and several sites in one face
  const auto f0 = *faces(m).begin();
  sites.push_back(Location<Mesh>(f0, {{ 0.5, 0.5, 0. }}));
  sites.push_back(Location<Mesh>(*std::next(faces(m).begin(), 10), {{ 0., 0., 1. }}));
  const auto f1 = *std::next(faces(m).begin(), 20);
  sites.push_back(Location<Mesh>(f1, {{ 0.2, 0.3, 0.5 }}));
  sites.push_back(Location<Mesh>(f1, {{ 0.25, 0.3, 0.45 }}));
  sites.push_back(Location<Mesh>(f1, {{ 0.6, 0.2, 0.2 }}));

  auto r = SV::insert_sites(m, sites);
  CHECK(CGAL::is_valid_polygon_mesh(r.mesh));
  CHECK(CGAL::is_triangle_mesh(r.mesh));
  CHECK(CGAL::is_closed(r.mesh));
  CHECK(CGAL::Polygon_mesh_processing::area(r.mesh) == Approx(CGAL::Polygon_mesh_processing::area(m)).epsilon(1e-12));
  REQUIRE(r.site_vertices.size() == sites.size());
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(CGAL::to_double(CGAL::squared_distance(r.mesh.point(r.site_vertices[i]), point_of(sites[i], m))) < 1e-24);
  // the vertex site reused the mesh vertex; the others are new
  CHECK(num_vertices(r.mesh) == num_vertices(m) + sites.size() - 1);
  CHECK(r.edges_split == 1);
  CHECK(non_delaunay_inner_edges(r) == 0);
  // every face lies in the input face it names
  for(auto f : faces(r.mesh))
  {
    const auto in = r.input_face[f];
    REQUIRE(in != Mesh::null_face());
    const auto h = halfedge(in, m);
    const K::Triangle_3 t(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    for(auto v : vertices_around_face(halfedge(f, r.mesh), r.mesh))
      CHECK(CGAL::to_double(CGAL::squared_distance(t, r.mesh.point(v))) < 1e-20);
  }
}

TEST_CASE("insertion: the diagram on the augmented mesh satisfies the invariants", "[insertion]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 2000;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 80, 12);
  auto r = SV::insert_sites(m, sites);
  CGAL::Biharmonic_embedding<Mesh> e(r.mesh);
  CGAL::Surface_voronoi_diagram<Mesh> vd(r.mesh, e, r.site_vertices);
  check_invariants(vd);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(vd.site_of(r.site_vertices[i]) == i);
}

} // namespace svd_test_site_insertion
