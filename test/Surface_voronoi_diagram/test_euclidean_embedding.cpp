// Tests of CGAL/Surface_voronoi_diagram/Euclidean_embedding.h: on a convex planar patch the
// Euclidean diagram is the plane's Voronoi diagram, which CGAL computes as the dual of a
// Delaunay triangulation.
#include "test_support.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_euclidean_embedding {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

TEST_CASE("euclidean: on a planar patch the diagram is CGAL's 2D Voronoi diagram", "[euclidean]")
{
  Mesh m;
  GEN::make_planar_grid(m, 41, 31, 1.0, 0.75, 0.2, 3);
  const auto sites = area_uniform_locations(m, 40, 77);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  check_invariants(vd);

  typedef CGAL::Delaunay_triangulation_2<K> DT;
  DT dt;
  std::map<K::Point_2, std::size_t> index;
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    const Point p = point_of(sites[i], m);
    index[K::Point_2(p.x(), p.y())] = i;
    dt.insert(K::Point_2(p.x(), p.y()));
  }

  // 1. every Voronoi vertex of the 2D diagram inside the patch is a Voronoi vertex of ours,
  //    and ours inside the patch are exactly those
  std::vector<K::Point_2> expected;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
  {
    const K::Point_2 c = dt.circumcenter(f);
    if(c.x() > 1e-6 && c.x() < 1 - 1e-6 && c.y() > 1e-6 && c.y() < 0.75 - 1e-6) expected.push_back(c);
  }
  Mesh out;
  auto is_vv = out.add_property_map<Mesh::Vertex_index, bool>("v:vv", false).first;
  SV::make_arrangement(vd, out, CGAL::parameters::vertex_is_constrained_map(is_vv));
  std::vector<K::Point_2> found;
  for(auto v : vertices(out))
    if(is_vv[v] && !is_border(v, out)) found.push_back(K::Point_2(out.point(v).x(), out.point(v).y()));
  CHECK(found.size() == expected.size());
  for(const K::Point_2& c : expected)
  {
    double best = 1e300;
    for(const K::Point_2& q : found) best = (std::min)(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(c, q))));
    CHECK(best < 1e-9);
  }

  // 2. neighbours: the Delaunay edges whose Voronoi edge crosses the patch
  std::size_t checked = 0;
  for(auto ed = dt.finite_edges_begin(); ed != dt.finite_edges_end(); ++ed)
  {
    const K::Point_2 a = ed->first->vertex(DT::cw(ed->second))->point();
    const K::Point_2 b = ed->first->vertex(DT::ccw(ed->second))->point();
    const std::size_t ia = index[a], ib = index[b];
    const auto& na = vd.neighbors(ia);
    const bool ours = std::find(na.begin(), na.end(), ib) != na.end();
    // the midpoint of a and b is on their Voronoi edge iff no other site is closer to it
    const K::Point_2 mid = CGAL::midpoint(a, b);
    const auto nearest = dt.nearest_vertex(mid);
    const double dm = CGAL::to_double(CGAL::squared_distance(mid, a));
    if(CGAL::to_double(CGAL::squared_distance(mid, nearest->point())) >= dm * (1 - 1e-12)
       && mid.x() > 0 && mid.x() < 1 && mid.y() > 0 && mid.y() < 0.75)
    {
      CHECK(ours);
      ++checked;
    }
  }
  CHECK(checked > 30);
}

TEST_CASE("euclidean: labels on a planar patch equal the nearest site", "[euclidean]")
{
  Mesh m;
  GEN::make_planar_grid(m, 25, 25, 1.0, 1.0, 0.2, 5);
  const auto sites = area_uniform_locations(m, 60, 8);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  std::size_t wrong = 0;
  for(const auto& l : area_uniform_locations(m, 3000, 9))
  {
    const Point p = point_of(l, m);
    std::size_t best = 0;
    double bd = 1e300;
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      const double d = CGAL::to_double(CGAL::squared_distance(p, point_of(sites[i], m)));
      if(d < bd) { bd = d; best = i; }
    }
    wrong += (vd.site_of(l) != best);
  }
  CHECK(wrong == 0);
}

} // namespace svd_test_euclidean_embedding
