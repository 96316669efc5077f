// Shared helpers of the test suite: mesh types, area-uniform sampling, and the invariants
// every diagram must satisfy.
#ifndef SVD_TEST_SUPPORT_H
#define SVD_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace svd_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron;

template <class TriangleMesh>
using Location = CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>;

/// n area-uniform random locations (deterministic for a seed)
template <class TriangleMesh>
std::vector<Location<TriangleMesh> > area_uniform_locations(const TriangleMesh& tm, std::size_t n, unsigned seed)
{
  return CGAL::Surface_voronoi::random_sites(tm, n, CGAL::parameters::random_seed(seed));
}

template <class TriangleMesh>
Point point_of(const Location<TriangleMesh>& l, const TriangleMesh& tm)
{
  return CGAL::Polygon_mesh_processing::construct_point(l, tm);
}

template <class TriangleMesh>
double border_length(const TriangleMesh& tm)
{
  double s = 0;
  auto vpm = get(CGAL::vertex_point, tm);
  for(auto h : halfedges(tm))
    if(is_border(h, tm))
      s += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  return s;
}

/// The invariants of DESIGN.md for a diagram of distinct, unweighted sites with repair:
/// areas add up, each site owns its own location, every cell is one piece, every face
/// reachable from a site is covered, and both sides of every edge agree (the arrangement
/// is a valid polygon mesh whose border is exactly the input's border).
/// With power weights (`unweighted` false) a site may lose its own location and a cell may
/// be empty; every non-empty cell is still one piece.
template <class Diagram>
void check_invariants(const Diagram& vd, bool unweighted = true)
{
  const auto& tm = vd.triangle_mesh();
  double sum = vd.unreached_area();
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
    sum += vd.cell_area(i);
  const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(tm));
  CHECK(sum == Approx(area).epsilon(1e-9));
  CHECK(vd.surface_area() == Approx(area).epsilon(1e-12));

  std::size_t own = 0, one_piece = 0;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
  {
    own += (vd.site_of(vd.site_location(i)) == i);
    one_piece += unweighted ? (vd.number_of_pieces(i) == 1) : (vd.number_of_pieces(i) <= 1);
  }
  if(unweighted)
    CHECK(own == vd.number_of_sites());
  CHECK(one_piece == vd.number_of_sites());
  CHECK(vd.statistics().broken_cells == 0);

  // unreached faces exactly in the components without sites
  typedef typename boost::graph_traits<typename Diagram::Triangle_mesh>::face_descriptor face_descriptor;
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t ncc = CGAL::Polygon_mesh_processing::connected_components(tm, fcc);
  std::vector<char> has_site(ncc, 0);
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
    has_site[get(fcc, vd.site_location(i).first)] = 1;
  std::size_t expected_unreached = 0;
  for(face_descriptor f : faces(tm))
    expected_unreached += has_site[get(fcc, f)] ? 0 : 1;
  CHECK(vd.number_of_unreached_faces() == expected_unreached);

  Mesh out;
  REQUIRE_NOTHROW(CGAL::Surface_voronoi::make_arrangement(vd, out));
  CHECK(CGAL::is_valid_polygon_mesh(out));
  CHECK(border_length(out) == Approx(border_length(tm)).epsilon(1e-9).margin(1e-12));
}

// Whether p lies on the outline of the square [lo, hi]^2 in x and y (to 1e-9).
inline bool on_square_outline(const Point& p, double lo, double hi)
{
  auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
  const bool in_x = p.x() > lo - 1e-9 && p.x() < hi + 1e-9, in_y = p.y() > lo - 1e-9 && p.y() < hi + 1e-9;
  return ((near(p.x(), lo) || near(p.x(), hi)) && in_y) || ((near(p.y(), lo) || near(p.y(), hi)) && in_x);
}

// The edges of `m` on the outline of the square [lo, hi]^2, marked in a new edge map
// "e:breakline": a closed loop of breaklines on a planar grid whose lines include lo and hi.
inline Mesh::Property_map<Mesh::Edge_index, bool> mark_square_outline(Mesh& m, double lo, double hi)
{
  auto loop = m.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
  for(Mesh::Edge_index e : m.edges())
    loop[e] = on_square_outline(m.point(m.source(m.halfedge(e))), lo, hi) && on_square_outline(m.point(m.target(m.halfedge(e))), lo, hi);
  return loop;
}

} // namespace svd_test

#endif
