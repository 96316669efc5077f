// Tests of CGAL/Surface_voronoi_diagram/voronoi_polygon_mesh.h: one face per disk cell, into
// Surface_mesh and Polyhedron_3; the faces tile a closed surface with its Euler
// characteristic, their vertices lie on bisectors (Euclidean distances to the sites), their
// adjacency is the diagram's; cells that are not disks are reported and the output stays valid.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/voronoi_polygon_mesh.h>
#include <test_meshes.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <map>
#include <set>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_voronoi_polygon_mesh {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

namespace {

typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;

template <class G>
long euler_characteristic(const G& g)
{
  return long(num_vertices(g)) - long(num_edges(g)) + long(num_faces(g));
}

template <class G>
std::size_t number_of_border_cycles(const G& g)
{
  std::set<typename boost::graph_traits<G>::halfedge_descriptor> seen;
  std::size_t cycles = 0;
  for(auto h : halfedges(g))
    if(is_border(h, g) && seen.insert(h).second)
    {
      ++cycles;
      for(auto k : CGAL::halfedges_around_face(h, g)) seen.insert(k);
    }
  return cycles;
}

// Euclidean distances from p to every site, ascending with the site index.
std::vector<std::pair<double, std::size_t> > distances_to_sites(const Euclidean_diagram& vd, const Point& p)
{
  std::vector<std::pair<double, std::size_t> > d;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
    d.emplace_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, vd.site_point(i)))), i);
  std::sort(d.begin(), d.end());
  return d;
}

// A site's point, moved to the surface by the diagram: a point of the torus at angle u
// around the axis and v around the tube.
Point torus_point(double major, double minor, double u, double v)
{
  const double rho = major + minor * std::cos(v);
  return Point(rho * std::cos(u), rho * std::sin(u), minor * std::sin(v));
}

} // namespace

TEST_CASE("voronoi polygon mesh: on a sphere every cell is one face, and the faces tile it", "[voronoi_polygon_mesh]")
{
  Mesh sphere;
  GEN::make_icosphere(sphere, 4, 1.0);
  Euclidean e(sphere);
  const Euclidean_diagram vd(sphere, e, area_uniform_locations(sphere, 40, 5));
  const std::size_t n = vd.number_of_sites();

  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, int>("f:site", -7).first;
  auto voronoi = out.add_property_map<Mesh::Vertex_index, bool>("v:voronoi", false).first;
  const std::vector<std::size_t> not_written =
      SV::make_voronoi_polygon_mesh(vd, out, CGAL::parameters::face_patch_map(site).vertex_is_constrained_map(voronoi));
  CHECK(not_written.empty());
  REQUIRE(out.number_of_faces() == n);
  CHECK(CGAL::is_valid_polygon_mesh(out));
  CHECK(CGAL::is_closed(out));
  CHECK(euler_characteristic(out) == euler_characteristic(sphere));

  // each site names exactly one face
  std::vector<int> faces_of_site(n, 0);
  for(Mesh::Face_index f : out.faces())
  {
    REQUIRE(site[f] >= 0);
    REQUIRE(std::size_t(site[f]) < n);
    ++faces_of_site[std::size_t(site[f])];
  }
  CHECK(std::count(faces_of_site.begin(), faces_of_site.end(), 1) == long(n));

  // every vertex of a face is on the boundary of that face's cell: its site is among the
  // nearest, with another site as near (a bisector); Voronoi vertices have three
  const double tolerance = 1e-9;
  std::size_t on_bisector = 0, at_three = 0, own_nearest = 0, corners = 0, marked = 0;
  for(Mesh::Vertex_index v : out.vertices())
  {
    const auto d = distances_to_sites(vd, out.point(v));
    on_bisector += (d[1].first - d[0].first < tolerance);
    if(voronoi[v])
    {
      ++marked;
      at_three += (d[2].first - d[0].first < tolerance);
    }
  }
  for(Mesh::Face_index f : out.faces())
    for(Mesh::Vertex_index v : vertices_around_face(out.halfedge(f), out))
    {
      ++corners;
      own_nearest += (std::sqrt(CGAL::squared_distance(out.point(v), vd.site_point(std::size_t(site[f])))) -
                      distances_to_sites(vd, out.point(v))[0].first < tolerance);
    }
  CHECK(on_bisector == out.number_of_vertices());
  CHECK(at_three == marked);
  CHECK(own_nearest == corners);
  // Euler on a sphere whose Voronoi vertices join three cells: 2 (n - 2) of them
  CHECK(marked == 2 * (n - 2));
  // and the others only bend: exactly two cells around
  CHECK(out.number_of_vertices() > marked);

  // adjacency of the faces is the diagram's neighbourhood
  for(Mesh::Face_index f : out.faces())
  {
    std::set<std::size_t> across;
    for(Mesh::Halfedge_index h : halfedges_around_face(out.halfedge(f), out))
      across.insert(std::size_t(site[out.face(out.opposite(h))]));
    const std::vector<std::size_t>& neighbors = vd.neighbors(std::size_t(site[f]));
    CHECK(across == std::set<std::size_t>(neighbors.begin(), neighbors.end()));
  }

  // each face bounds roughly its cell's area (a fan from the boundary's centroid, flat while
  // the cell is curved), and faces outwards as the sphere does
  double total = 0;
  for(Mesh::Face_index f : out.faces())
  {
    std::vector<Point> p;
    for(Mesh::Vertex_index v : vertices_around_face(out.halfedge(f), out)) p.push_back(out.point(v));
    K::Vector_3 c(0, 0, 0);
    for(const Point& q : p) c = c + (q - CGAL::ORIGIN);
    const Point centroid = CGAL::ORIGIN + c / double(p.size());
    double area = 0;
    K::Vector_3 normal(0, 0, 0);
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      const K::Vector_3 cross = CGAL::cross_product(p[k] - centroid, p[(k + 1) % p.size()] - centroid);
      area += std::sqrt(cross.squared_length()) / 2;
      normal = normal + cross;
    }
    total += area;
    CHECK(area == Approx(vd.cell_area(std::size_t(site[f]))).epsilon(0.1));
    CHECK(normal * (centroid - CGAL::ORIGIN) > 0);
  }
  CHECK(total == Approx(vd.surface_area()).epsilon(0.05));

  // the same into a Polyhedron_3, with an associative map
  Polyhedron p;
  std::map<Polyhedron::Face_handle, std::size_t> psite;
  CHECK(SV::make_voronoi_polygon_mesh(vd, p, CGAL::parameters::face_patch_map(boost::make_assoc_property_map(psite))).empty());
  CHECK(CGAL::is_valid_polygon_mesh(p));
  CHECK(CGAL::is_closed(p));
  CHECK(num_faces(p) == n);
  CHECK(num_vertices(p) == out.number_of_vertices());
  CHECK(euler_characteristic(p) == 2);
  std::set<std::size_t> psites;
  for(const auto& fs : psite) psites.insert(fs.second);
  CHECK(psites.size() == n);
}

TEST_CASE("voronoi polygon mesh: a torus tiled by disk cells keeps Euler characteristic 0", "[voronoi_polygon_mesh]")
{
  Mesh torus;
  GEN::make_torus(torus, 1.0, 0.4, 90, 36);
  Euclidean e(torus);
  const Euclidean_diagram vd(torus, e, SV::blue_noise_sites(torus, 60, CGAL::parameters::random_seed(3)));
  Mesh out;
  const std::vector<std::size_t> not_written = SV::make_voronoi_polygon_mesh(vd, out);
  CHECK(not_written.empty());
  CHECK(out.number_of_faces() == vd.number_of_sites());
  CHECK(CGAL::is_valid_polygon_mesh(out));
  CHECK(CGAL::is_closed(out));
  CHECK(euler_characteristic(out) == 0);
}

TEST_CASE("voronoi polygon mesh: a cell around a hole is reported, the rest stays a valid mesh", "[voronoi_polygon_mesh]")
{
  // A loop of breaklines around the square [0.4, 0.6]^2 of a unit square, one site inside it;
  // outside, the site just below it is the nearest all around it: its cell is the unit square
  // minus the small one, an annulus, not a disk
  Mesh grid;
  GEN::make_planar_grid(grid, 41, 41, 1.0, 1.0);   // spacing 0.025
  const double lo = 0.4, hi = 0.6;
  auto on_square = [&](const Point& p) { return on_square_outline(p, lo, hi); };
  const auto loop = mark_square_outline(grid, lo, hi);
  const std::vector<Point> sites = { Point(0.5, 0.5, 0), Point(0.5, 0.2, 0), Point(0.05, 0.95, 0), Point(0.95, 0.95, 0) };
  Euclidean e(grid);
  const Euclidean_diagram vd(grid, e, sites, CGAL::parameters::edge_is_constrained_map(loop));
  REQUIRE(vd.cell_area(0) == Approx(0.04).epsilon(1e-12));

  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::size_t>("f:site", 0).first;
  const std::vector<std::size_t> not_written = SV::make_voronoi_polygon_mesh(vd, out, CGAL::parameters::face_patch_map(site));
  CHECK(not_written == std::vector<std::size_t>{ 1 });
  CHECK(out.number_of_faces() == 3);
  CHECK(CGAL::is_valid_polygon_mesh(out));
  for(Mesh::Face_index f : out.faces()) CHECK(site[f] != 1);
  // two components left, each a disk: the small square, and the two upper cells
  CHECK(number_of_border_cycles(out) == 2);
  CHECK(euler_characteristic(out) == 2);
  // the small square's face is the breakline loop: its corners among its vertices, area 0.04
  for(Mesh::Face_index f : out.faces())
  {
    if(site[f] != 0) continue;
    std::vector<Point> p;
    for(Mesh::Vertex_index v : vertices_around_face(out.halfedge(f), out)) p.push_back(out.point(v));
    std::size_t on = 0;
    double twice = 0;
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      on += on_square(p[k]);
      twice += p[k].x() * p[(k + 1) % p.size()].y() - p[(k + 1) % p.size()].x() * p[k].y();
    }
    CHECK(on == p.size());
    CHECK(twice / 2 == Approx(0.04).epsilon(1e-12));
  }

  // three sites around a torus: three bands, nothing written, nothing left over
  const double major = 1.0, minor = 0.4, pi = std::acos(-1.);
  Mesh torus;
  GEN::make_torus(torus, major, minor, 90, 36);
  Euclidean et(torus);
  std::vector<Point> three;
  for(double u : { 0.0, 2 * pi / 3, 4 * pi / 3 }) three.push_back(torus_point(major, minor, u, 0.0));
  const Euclidean_diagram bands(torus, et, three);
  Polyhedron p;
  CHECK(SV::make_voronoi_polygon_mesh(bands, p) == std::vector<std::size_t>{ 0, 1, 2 });
  CHECK(num_faces(p) == 0);
  CHECK(num_vertices(p) == 0);
}

TEST_CASE("voronoi polygon mesh: on a planar patch the faces are the cells, the border included", "[voronoi_polygon_mesh]")
{
  Mesh grid;
  GEN::make_planar_grid(grid, 40, 40, 1.0, 1.0, 0.2, 4);
  Euclidean e(grid);
  const Euclidean_diagram vd(grid, e, area_uniform_locations(grid, 25, 8));
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, int>("f:site", -1).first;
  CHECK(SV::make_voronoi_polygon_mesh(vd, out, CGAL::parameters::face_patch_map(site)).empty());
  CHECK(out.number_of_faces() == vd.number_of_sites());
  CHECK(CGAL::is_valid_polygon_mesh(out));
  // a disk tiled by disks: one border loop, as long as the square's, and Euler 1
  CHECK(number_of_border_cycles(out) == 1);
  CHECK(border_length(out) == Approx(4.0).epsilon(1e-9));
  CHECK(euler_characteristic(out) == 1);
  // flat faces: their areas (shoelace in the plane) are the cells' areas
  for(Mesh::Face_index f : out.faces())
  {
    std::vector<Point> p;
    for(Mesh::Vertex_index v : vertices_around_face(out.halfedge(f), out)) p.push_back(out.point(v));
    double twice = 0;
    for(std::size_t k = 0; k < p.size(); ++k)
      twice += p[k].x() * p[(k + 1) % p.size()].y() - p[(k + 1) % p.size()].x() * p[k].y();
    CHECK(twice / 2 == Approx(vd.cell_area(std::size_t(site[f]))).epsilon(1e-9));
  }
}


TEST_CASE("voronoi polygon mesh: where two faces only touch at a point, each gets its own vertex", "[voronoi_polygon_mesh]")
{
  // A diamond of breaklines standing on the bottom side of a unit square, on grid diagonals,
  // with no site inside: the unreached diamond touches the border at its lowest corner only.
  // Around that point: the left cell, the diamond, the right cell, the outside.
  Mesh grid;
  GEN::make_planar_grid(grid, 41, 41, 1.0, 1.0);   // spacing 0.025; the diagonals line up
  auto on_diamond = [](const Point& p) { return std::abs(std::abs(p.x() - 0.5) + std::abs(p.y() - 0.1) - 0.1) < 1e-9; };
  auto loop = grid.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
  std::size_t marked = 0;
  for(Mesh::Edge_index ed : grid.edges())
    marked += (loop[ed] = on_diamond(grid.point(grid.source(grid.halfedge(ed)))) && on_diamond(grid.point(grid.target(grid.halfedge(ed)))));
  REQUIRE(marked == 16);
  const std::vector<Point> sites = { Point(0.2, 0.2, 0), Point(0.8, 0.2, 0), Point(0.5, 0.8, 0) };
  Euclidean e(grid);
  const Euclidean_diagram vd(grid, e, sites, CGAL::parameters::edge_is_constrained_map(loop));
  REQUIRE(vd.unreached_area() == Approx(0.02).epsilon(1e-12));

  Mesh out;
  CHECK(SV::make_voronoi_polygon_mesh(vd, out).empty());
  CHECK(out.number_of_faces() == 3);
  CHECK(CGAL::is_valid_polygon_mesh(out));
  // the corner is two vertices, one per face touching there, so that no vertex is pinched:
  // at most one border halfedge into each vertex
  std::size_t at_corner = 0, pinched = 0;
  for(Mesh::Vertex_index v : out.vertices())
  {
    at_corner += (out.point(v) == Point(0.5, 0, 0));
    std::size_t border_in = 0;
    for(Mesh::Halfedge_index h : halfedges_around_target(out.halfedge(v), out)) border_in += out.is_border(h);
    pinched += (border_in > 1);
  }
  CHECK(at_corner == 2);
  CHECK(pinched == 0);
  // the square minus a diamond on its side, cut open at the touching point: a disk
  CHECK(number_of_border_cycles(out) == 1);
  CHECK(euler_characteristic(out) == 1);
}

} // namespace svd_test_voronoi_polygon_mesh
