// Tests of CGAL/Surface_voronoi_diagram.h: invariants on every metric and several meshes,
// ties, determinism (also across threads), thin walls, the RVD baseline against brute force, and bad input.
#include "test_support.h"

#include <CGAL/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/Prepared_mesh.h>
#include <CGAL/Surface_voronoi_diagram/locate_in_face.h>
#include <CGAL/Surface_voronoi_diagram/validate_input.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <test_meshes.h>
#include <fidelity.h>   // benchmark/Surface_voronoi_diagram: the fidelity measurement

#include <map>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_surface_voronoi_diagram {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;

typedef CGAL::Biharmonic_embedding<Mesh> Biharmonic;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

namespace {

std::vector<Mesh> test_meshes()
{
  std::vector<Mesh> ms(5);
  GEN::make_icosphere(ms[0], 3, 1.0);
  GEN::make_torus(ms[1], 1.0, 0.3, 60, 20);
  GEN::make_planar_grid(ms[2], 30, 25, 1.0, 0.8, 0.2, 7);   // with a border
  GEN::Lampshade_options lo;
  lo.target_vertices = 3000;
  GEN::make_thin_lampshade(ms[3], lo);
  GEN::U_fold_options uo;
  uo.target_vertices = 3000;
  GEN::make_u_fold(ms[4], uo);
  return ms;
}

// Meshes of several chunks for the parallel loops (which cut 4096 to 8192 faces at a time):
// a thin lampshade of 12k vertices and a torus of 20k faces.
std::vector<Mesh> thin_lampshade_and_torus()
{
  std::vector<Mesh> ms(2);
  GEN::Lampshade_options lo;
  lo.target_vertices = 12000;
  GEN::make_thin_lampshade(ms[0], lo);
  GEN::make_torus(ms[1], 1.0, 0.3, 160, 64);
  return ms;
}

// Bit-level summary of a partition, to compare runs.
template <class Diagram>
std::vector<double> fingerprint(const Diagram& vd)
{
  std::vector<double> f;
  for(const auto& v : SV::internal::Diagram_access::data(vd).partition.vertices)
    f.insert(f.end(), { v.point.x(), v.point.y(), v.point.z() });
  for(const auto& p : SV::internal::Diagram_access::data(vd).partition.pieces)
  {
    f.push_back(double(p.face));
    f.push_back(double(p.site));
    f.push_back(p.area);
    for(std::size_t id : p.vertices) f.push_back(double(id));
  }
  return f;
}

// The labels of `samples` area-uniform points of m against the brute-force nearest site
// (points whose two nearest sites tie within rounding skipped): {points checked, wrong labels}.
template <class Diagram, class Locations>
std::pair<std::size_t, std::size_t> check_nearest_site_labels(const Diagram& vd, const Mesh& m, const Locations& sites,
                                                              std::size_t samples, unsigned seed)
{
  std::vector<Point> sp;
  for(const auto& s : sites) sp.push_back(point_of(s, m));
  std::size_t wrong = 0, checked = 0;
  for(const auto& l : area_uniform_locations(m, samples, seed))
  {
    const Point p = point_of(l, m);
    std::vector<std::pair<double, std::size_t> > d;
    for(std::size_t i = 0; i < sp.size(); ++i) d.emplace_back(CGAL::to_double(CGAL::squared_distance(p, sp[i])), i);
    std::partial_sort(d.begin(), d.begin() + 2, d.end());
    if(d[1].first - d[0].first < 1e-12 * (1 + d[0].first)) continue;   // a tie within rounding
    ++checked;
    wrong += (vd.site_of(l) != d[0].second);
  }
  return { checked, wrong };
}

} // namespace


TEST_CASE("diagram: invariants for the biharmonic metric on several meshes", "[diagram]")
{
  std::size_t k = 0;
  for(const Mesh& m : test_meshes())
  {
    INFO("mesh " << k++);
    Biharmonic e(m);
    for(std::size_t n : { std::size_t(7), std::size_t(60), std::size_t(400) })
    {
      INFO(n << " sites");
      CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, area_uniform_locations(m, n, unsigned(n)));
      check_invariants(vd);
    }
  }
}

TEST_CASE("diagram: invariants for the Euclidean metric (EDBVD) on several meshes", "[diagram]")
{
  std::size_t k = 0;
  for(const Mesh& m : test_meshes())
  {
    INFO("mesh " << k++);
    Euclidean e(m);
    for(std::size_t n : { std::size_t(5), std::size_t(80), std::size_t(700) })
    {
      INFO(n << " sites");
      CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, area_uniform_locations(m, n, 11u + unsigned(n)));
      check_invariants(vd);
    }
  }
}

TEST_CASE("diagram: sites given as vertices and as points", "[diagram]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.3, 40, 16);
  Biharmonic e(m);
  std::vector<Mesh::Vertex_index> vs;
  for(auto v : vertices(m))
    if(std::size_t(v) % 37 == 0) vs.push_back(v);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, vs);
  check_invariants(vd);
  for(std::size_t i = 0; i < vs.size(); ++i)
  {
    CHECK(vd.site_of(vs[i]) == i);
    CHECK(CGAL::squared_distance(vd.site_point(i), m.point(vs[i])) == 0);
  }
  std::vector<Point> ps;
  for(auto l : area_uniform_locations(m, 50, 3))
  {
    const Point p = point_of(l, m);
    ps.push_back(Point(p.x() * 1.00001, p.y() * 1.00001, p.z()));   // slightly off the surface
  }
  CGAL::Surface_voronoi_diagram<Mesh> vp(m, e, ps);
  check_invariants(vp);
}

TEST_CASE("diagram: the same run twice is bit-identical", "[diagram]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 2500;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 150, 5);
  Biharmonic e1(m), e2(m);
  CGAL::Surface_voronoi_diagram<Mesh> a(m, e1, sites), b(m, e2, sites);
  CHECK(fingerprint(a) == fingerprint(b));
}

#ifdef CGAL_LINKED_WITH_TBB
TEST_CASE("indexed mesh: the copy built in chunks on several threads is the sequential one", "[diagram][parallel]")
{
  // Meshes of several chunks of faces (8192), one with a border; and one with removed faces,
  // whose descriptors are not indices (built sequentially whatever is asked).
  std::vector<Mesh> ms(3);
  GEN::make_torus(ms[0], 1.0, 0.3, 160, 64);
  GEN::make_planar_grid(ms[1], 120, 100, 1.0, 0.8, 0., 0);
  GEN::make_planar_grid(ms[2], 120, 100, 1.0, 0.8, 0., 0);
  CGAL::Euler::remove_face(halfedge(*faces(ms[2]).begin(), ms[2]), ms[2]);
  for(std::size_t k = 0; k < ms.size(); ++k)
  {
    INFO("mesh " << k << ", " << num_faces(ms[k]) << " faces");
    REQUIRE(num_faces(ms[k]) > 2 * 8192);
    const SV::internal::Indexed_mesh<Mesh> a(ms[k], get(CGAL::vertex_point, ms[k]), false);
    for(int threads : { 1, 2, 4 })
    {
      INFO(threads << " threads");
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      const SV::internal::Indexed_mesh<Mesh> b(ms[k], get(CGAL::vertex_point, ms[k]), true);
      CHECK(a.points == b.points);
      CHECK(a.triangles == b.triangles);
      CHECK(a.neighbors == b.neighbors);
      CHECK(a.edges == b.edges);
      CHECK(a.edge_vertices == b.edge_vertices);
      CHECK(a.face_areas == b.face_areas);
      CHECK(a.face_component == b.face_component);
      CHECK(a.total_area == b.total_area);
      for(std::size_t f = 0; f < a.number_of_faces(); ++f)
        CHECK(a.face_handles[f] == b.face_handles[f]);
    }
    // every edge named once, by the lower of its faces, and found again from the other
    std::vector<int> uses(a.number_of_edges(), 0);
    for(std::size_t f = 0; f < a.number_of_faces(); ++f)
      for(int l = 0; l < 3; ++l)
      {
        ++uses[a.edges[f][l]];
        const auto& ev = a.edge_vertices[a.edges[f][l]];
        const auto u = a.triangles[f][l], w = a.triangles[f][(l + 1) % 3];
        CHECK(ev[0] == (std::min)(u, w));
        CHECK(ev[1] == (std::max)(u, w));
      }
    for(std::size_t e = 0; e < uses.size(); ++e) CHECK((uses[e] == 1 || uses[e] == 2));
  }
}

TEST_CASE("diagram: a parallel diagram is the sequential one, bit for bit, on any number of threads", "[diagram][parallel]")
{
  // Meshes of several chunks (the parallel loops cut 4096 to 8192 faces or pieces at a time),
  // with cells the repair must mend (the lampshade's thin wall, biharmonic) and with exact
  // ties (a lattice of sites on a grid: Voronoi vertices on mesh vertices and edges).
  typedef CGAL::Surface_voronoi_diagram<Mesh, Biharmonic> Sequential;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Biharmonic, CGAL::Default, CGAL::Default, CGAL::Parallel_tag> Parallel;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Sequential_euclidean;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean, CGAL::Default, CGAL::Default, CGAL::Parallel_tag> Parallel_euclidean;
  // The last mesh is large enough for the propagation to run in blocks.
  std::vector<Mesh> ms = thin_lampshade_and_torus();
  ms.resize(4);
  GEN::make_planar_grid(ms[2], 120, 100, 1.0, 0.8, 0., 0);
  GEN::Lampshade_options lo;
  lo.target_vertices = 36000;
  GEN::make_thin_lampshade(ms[3], lo);
  for(std::size_t k = 0; k < ms.size(); ++k)
  {
    INFO("mesh " << k << ", " << num_faces(ms[k]) << " faces");
    REQUIRE(num_faces(ms[k]) > 2 * 8192);
    std::vector<Mesh::Vertex_index> lattice;
    for(Mesh::Vertex_index v : vertices(ms[k]))
      if(std::size_t(v) % 97 == 0) lattice.push_back(v);
    const auto random_sites = area_uniform_locations(ms[k], 900, 11);
    Biharmonic metric(ms[k]);
    Euclidean euclidean(ms[k]);
    const Sequential a(ms[k], metric, random_sites);
    const Sequential_euclidean e(ms[k], euclidean, lattice);
    CHECK((a.statistics().propagation_blocks > 1) == (k == 3));
    CHECK(a.statistics().broken_cells == 0);
    for(int threads : { 1, 2, 4 })
    {
      INFO(threads << " threads");
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      const Parallel b(ms[k], metric, random_sites);
      CHECK(fingerprint(a) == fingerprint(b));
      CHECK(a.statistics().broken_cells_before_repair == b.statistics().broken_cells_before_repair);
      CHECK(a.statistics().welded_vertices == b.statistics().welded_vertices);
      CHECK(a.statistics().inserted_vertices == b.statistics().inserted_vertices);
      for(std::size_t i = 0; i < random_sites.size(); ++i)
        CHECK(a.neighbors(i) == b.neighbors(i));
      const Parallel_euclidean f(ms[k], euclidean, lattice);
      CHECK(fingerprint(e) == fingerprint(f));
      CHECK(e.statistics().welded_vertices == f.statistics().welded_vertices);
    }
  }
}

// The geodesic metric without its concurrent queries: the diagram propagates in one global order.
struct Geodesic_one_thread : SV::Geodesic_metric<Mesh>
{
  using SV::Geodesic_metric<Mesh>::Geodesic_metric;
  typedef CGAL::Tag_false Has_concurrent_squared_distance;
};

TEST_CASE("diagram: the geodesic metric propagates in blocks on any number of threads, to the cells of one global order", "[diagram][parallel][geodesic]")
{
  // Threads ask the fronts of the geodesic metric at once (a lock per front), so its diagram
  // propagates in blocks: the same diagram on 1, 2 and 4 threads, and here the same cells as
  // the propagation in one order (a thin wall and a torus, 600 sites, blocks of 4096 faces).
  typedef SV::Geodesic_metric<Mesh> Geodesic;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Geodesic> Sequential;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Geodesic, CGAL::Default, CGAL::Default, CGAL::Parallel_tag> Parallel;
  const std::vector<Mesh> ms = thin_lampshade_and_torus();
  for(std::size_t k = 0; k < ms.size(); ++k)
  {
    INFO("mesh " << k << ", " << num_faces(ms[k]) << " faces");
    const auto sites = area_uniform_locations(ms[k], 600, 5);
    Geodesic metric(ms[k]);
    const Sequential a(ms[k], metric, sites);
    CHECK(a.statistics().propagation_blocks >= 4);
    CHECK(a.statistics().broken_cells == 0);
    double sum = a.unreached_area();
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      sum += a.cell_area(i);
      CHECK(a.site_of(sites[i]) == i);
    }
    CHECK(sum == Approx(CGAL::to_double(CGAL::Polygon_mesh_processing::area(ms[k]))).epsilon(1e-9));
    for(int threads : { 1, 2, 4 })
    {
      INFO(threads << " threads");
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      const Parallel b(ms[k], metric, sites);
      CHECK(fingerprint(a) == fingerprint(b));
      CHECK(a.statistics().broken_cells_before_repair == b.statistics().broken_cells_before_repair);
      CHECK(metric.number_of_computed_distances() > 0);
    }
    Geodesic_one_thread one_order(ms[k]);
    const CGAL::Surface_voronoi_diagram<Mesh, Geodesic_one_thread> c(ms[k], one_order, sites);
    CHECK(c.statistics().propagation_blocks == 1);
    for(Mesh::Vertex_index v : vertices(ms[k]))
      CHECK(a.site_of(v) == c.site_of(v));
    for(std::size_t i = 0; i < sites.size(); ++i)
      CHECK(a.cell_area(i) == Approx(c.cell_area(i)).epsilon(1e-9));
  }
}
#endif

TEST_CASE("diagram: symmetric layouts with exact ties are consistent and deterministic", "[diagram][ties]")
{
  // A regular grid with mirror-symmetric sites: bisectors run exactly along mesh edges and
  // Voronoi vertices fall exactly on mesh vertices, so the tie rule decides everything.
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  std::vector<Point> sites = { Point(0.25, 0.25, 0), Point(0.75, 0.25, 0), Point(0.25, 0.75, 0), Point(0.75, 0.75, 0),
                               Point(0.5, 0.5, 0), Point(0.5, 0.1, 0), Point(0.5, 0.9, 0), Point(0.1, 0.5, 0), Point(0.9, 0.5, 0) };
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  check_invariants(vd);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> again(m, e, sites);
  CHECK(fingerprint(vd) == fingerprint(again));
  // mirror images have equal areas (ties only move measure-zero sets)
  CHECK(vd.cell_area(0) == Approx(vd.cell_area(1)).epsilon(1e-12));
  CHECK(vd.cell_area(0) == Approx(vd.cell_area(3)).epsilon(1e-12));
  CHECK(vd.cell_area(5) == Approx(vd.cell_area(6)).epsilon(1e-12));
  CHECK(vd.cell_area(7) == Approx(vd.cell_area(8)).epsilon(1e-12));
  CHECK(vd.cell_area(5) == Approx(vd.cell_area(7)).epsilon(1e-12));
  // the mesh vertex at (0.5, 0.3) is equidistant from sites 0, 1 and 4? No: from 4 and 5 only;
  // a point exactly on the bisector of 0 and 1 goes to the lower index
  for(auto v : vertices(m))
  {
    const Point p = m.point(v);
    if(p.x() == 0.5 && p.y() == 0.05) CHECK(vd.site_of(v) == 5);
  }

  // the same with the biharmonic metric of the grid (symmetric too)
  Biharmonic b(m);
  CGAL::Surface_voronoi_diagram<Mesh> vb(m, b, sites);
  check_invariants(vb);
}

TEST_CASE("diagram: four sites around a grid vertex tie there", "[diagram][ties]")
{
  Mesh m;
  GEN::make_planar_grid(m, 9, 9, 1.0, 1.0);
  // sites symmetric about (0.5, 0.5), off the grid lines: the centre is a 4-fold tie
  std::vector<Point> sites = { Point(0.3, 0.3, 0), Point(0.7, 0.3, 0), Point(0.3, 0.7, 0), Point(0.7, 0.7, 0) };
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  check_invariants(vd);
  for(std::size_t i = 0; i < 4; ++i)
    CHECK(vd.cell_area(i) == Approx(0.25).epsilon(1e-12));
}

TEST_CASE("diagram: the propagation in blocks gives the brute-force nearest site where cells are whole", "[diagram][blocks]")
{
  // A torus of 72,000 faces and 800 sites: the propagation runs in blocks (rounds in which
  // fields cross from block to block). On a smooth surface whose cells are all whole, the
  // Euclidean cells are the restricted Voronoi diagram's: each point is labelled with its
  // nearest site.
  Mesh m;
  GEN::make_torus(m, 1.0, 0.3, 300, 120);
  REQUIRE(num_faces(m) >= 4 * 16384);
  Euclidean e(m);
  const auto sites = area_uniform_locations(m, 800, 23);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  CHECK(vd.statistics().propagation_blocks >= 4);
  CHECK(vd.statistics().propagation_rounds >= 2);
  CHECK(vd.statistics().broken_cells == 0);
  const auto [checked, wrong] = check_nearest_site_labels(vd, m, sites, 6000, 77);
  CHECK(checked > 5900);
  CHECK(wrong == 0);
  double sum = vd.unreached_area();
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i)
  {
    sum += vd.cell_area(i);
    CHECK(vd.site_of(sites[i]) == i);   // each site owns its own location
  }
  CHECK(sum == Approx(CGAL::to_double(CGAL::Polygon_mesh_processing::area(m))).epsilon(1e-9));
}

TEST_CASE("diagram: RVD labels equal the brute-force nearest site", "[diagram][rvd]")
{
  std::size_t k = 0;
  for(const Mesh& m : test_meshes())
  {
    INFO("mesh " << k++);
    Euclidean e(m);
    const auto sites = area_uniform_locations(m, 120, 17);
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites,
                                                      SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
    const auto [checked, wrong] = check_nearest_site_labels(vd, m, sites, 4000, 99);
    CHECK(checked > 3900);
    CHECK(wrong == 0);
    // the partition covers the surface, pieces may be disconnected (no repair)
    double sum = vd.unreached_area();
    for(std::size_t i = 0; i < vd.number_of_sites(); ++i) sum += vd.cell_area(i);
    CHECK(sum == Approx(CGAL::to_double(CGAL::Polygon_mesh_processing::area(m))).epsilon(1e-9));
  }
}

TEST_CASE("diagram: biharmonic cells do not reach through thin walls, RVD cells do", "[diagram][thin]")
{
  // Tolerance: at most 0.5% of the area of a biharmonic diagram may be assigned to a site
  // more than 3x farther along the surface than the geodesically nearest site.
  std::vector<Mesh> ms(3);
  GEN::Lampshade_options lo;
  lo.target_vertices = 3000;
  GEN::make_thin_lampshade(ms[0], lo);
  GEN::U_fold_options uo;
  uo.target_vertices = 3000;
  GEN::make_u_fold(ms[1], uo);
  GEN::Slab_options so;
  so.target_vertices = 3000;
  so.thickness = 0.003;
  GEN::make_thin_slab(ms[2], so);
  const char* names[] = { "lampshade", "u_fold", "slab" };
  for(std::size_t k = 0; k < ms.size(); ++k)
  {
    const Mesh& m = ms[k];
    const auto sites = area_uniform_locations(m, 40, 21);
    Biharmonic b(m);
    CGAL::Surface_voronoi_diagram<Mesh> vb(m, b, sites);
    Euclidean e(m);
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vr(m, e, sites,
                                                      SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
    const svd_bench::Fidelity_report bh = svd_bench::measure_fidelity(vb, 2000, 1234, 40);
    const svd_bench::Fidelity_report rvd = svd_bench::measure_fidelity(vr, 2000, 1234, 6);
    INFO(names[k] << ": area through a wall, biharmonic <= " << bh.through_wall_upper << ", RVD >= " << rvd.through_wall_lower);
    CHECK(bh.through_wall_upper <= 0.005);
    CHECK(rvd.through_wall_lower >= 0.03);   // decided by fast marching; 6 exact trees at the threshold
  }
}

TEST_CASE("diagram: a component without sites is unreached, not an error", "[diagram]")
{
  Mesh a, b;
  GEN::make_icosphere(a, 3, 1.0);
  GEN::make_icosphere(b, 2, 0.5);
  Mesh m = a;
  for(auto v : vertices(b)) b.point(v) = b.point(v) + K::Vector_3(4, 0, 0);
  CGAL::copy_face_graph(b, m);
  std::vector<Location<Mesh> > sites;
  for(const auto& l : area_uniform_locations(m, 400, 8))
    if(point_of(l, m).x() < 2) sites.push_back(l);
  Biharmonic e(m);
  CGAL::Surface_voronoi_diagram<Mesh> vd(m, e, sites);
  check_invariants(vd);
  CHECK(vd.number_of_unreached_faces() == num_faces(b));
  CHECK(vd.unreached_area() == Approx(CGAL::to_double(CGAL::Polygon_mesh_processing::area(b))).epsilon(1e-9));
  CHECK(vd.statistics().unreached_components == 1);
}

TEST_CASE("diagram: the arrangement's faces read from the diagram are those make_arrangement() builds", "[diagram][arrangement]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  Euclidean e(m);
  SV::Stage_times times;
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, area_uniform_locations(m, 30, 5), SV::parameters::stage_times(&times));
  for(const char* stage : { "setup", "propagation", "cutting", "repair" })
    CHECK(times.seconds.count(stage) == 1);
  CHECK(times["no such stage"] == 0.);
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int64_t>("f:site", -2).first;
  auto input = out.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input").first;
  SV::make_arrangement(vd, out, SV::parameters::input_face_map(input, CGAL::parameters::face_patch_map(site)));
  REQUIRE(out.number_of_faces() == vd.number_of_arrangement_faces());
  REQUIRE(vd.number_of_arrangement_faces() > num_faces(m));
  std::size_t k = 0;
  for(Mesh::Face_index f : out.faces())
  {
    const std::size_t s = vd.arrangement_face_site(k);
    CHECK(site[f] == (s == vd.no_site ? std::int64_t(-1) : std::int64_t(s)));
    CHECK(input[f] == vd.arrangement_input_face(k));
    std::vector<Point> ours, theirs;
    for(std::uint32_t id : vd.arrangement_face_vertices(k)) ours.push_back(vd.arrangement_point(id));
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(out.halfedge(f), out)) theirs.push_back(out.point(v));
    // the same cycle, from wherever the output face starts
    REQUIRE(ours.size() == theirs.size());
    const auto start = std::find(theirs.begin(), theirs.end(), ours.front());
    REQUIRE(start != theirs.end());
    std::rotate(theirs.begin(), start, theirs.end());
    CHECK(ours == theirs);
    ++k;
  }

  // locate_in_face() is PMP's on a face that is not a needle
  const Mesh::Face_index f = *faces(m).begin();
  const Point p = CGAL::centroid(m.point(target(next(halfedge(f, m), m), m)), m.point(target(halfedge(f, m), m)),
                                 m.point(source(halfedge(f, m), m)));
  const auto ours = SV::locate_in_face(p, f, m);
  const auto pmp = CGAL::Polygon_mesh_processing::locate_in_face(p, f, m);
  CHECK(ours.first == f);
  CHECK(ours.second == pmp.second);
}

TEST_CASE("diagram: a prepared mesh is shared only where it is one of the same points", "[diagram]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  const auto vpm = get(CGAL::vertex_point, m);
  const auto sites = area_uniform_locations(m, 40, 3);
  const SV::Prepared_mesh<Mesh> prepared(m);
  const auto copy = prepared.indexed_mesh();
  CHECK(&prepared.triangle_mesh() == &m);
  CHECK(SV::internal::shared_or_new_indexed_mesh(copy, m, vpm) == copy);

  // another mesh with the same points and faces is not the same mesh
  Mesh twin = m;
  const auto other = SV::internal::shared_or_new_indexed_mesh(copy, twin, get(CGAL::vertex_point, twin));
  CHECK(other != copy);
  CHECK(other->source_mesh == &twin);

  // a vertex moved after the copy was made: a new copy, and the diagram given the stale one
  // is the diagram of the moved mesh
  const Mesh::Vertex_index moved = *vertices(m).begin();
  put(vpm, moved, Point(0.3, 0.2, 1.4));
  const auto fresh = SV::internal::shared_or_new_indexed_mesh(copy, m, vpm);
  REQUIRE(fresh != copy);
  CHECK(fresh->points[0] == SV::internal::to_point_d(get(vpm, moved)));
  Euclidean e(m);
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> own(m, e, sites);
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> given(m, e, sites, SV::parameters::prepared_mesh(prepared));
  CHECK(given.statistics().surface_area == own.statistics().surface_area);
  for(std::size_t i = 0; i < sites.size(); ++i)
    CHECK(given.cell_area(i) == own.cell_area(i));

  // validate_input() on the shared copy, with the reader's checks taken as made, still finds
  // what the reader does not check: here a face of zero area
  Mesh flat;
  GEN::make_icosphere(flat, 1, 1.0);
  const Mesh::Face_index f = *faces(flat).begin();
  const auto h = halfedge(f, flat);
  put(get(CGAL::vertex_point, flat), target(h, flat), get(get(CGAL::vertex_point, flat), source(h, flat)));
  const SV::Prepared_mesh<Mesh> flat_prepared(flat, SV::parameters::checked_mesh_topology(true));
  std::vector<SV::Input_problem> with_prepared = SV::validate_input(flat, std::vector<Point>{ Point(0, 0, 1) },
                                                                 SV::parameters::prepared_mesh(flat_prepared));
  std::vector<SV::Input_problem> without = SV::validate_input(flat, std::vector<Point>{ Point(0, 0, 1) });
  REQUIRE(!without.empty());
  REQUIRE(with_prepared.size() == without.size());
  for(std::size_t k = 0; k < without.size(); ++k)
  {
    CHECK(with_prepared[k].kind == without[k].kind);
    CHECK(with_prepared[k].element == without[k].element);
  }
  CHECK(std::any_of(without.begin(), without.end(), [](const SV::Input_problem& p) { return p.kind == SV::Input_problem::ZERO_AREA_FACE; }));
}

TEST_CASE("diagram: bad input gives clear errors", "[diagram][errors]")
{
  Mesh m;
  GEN::make_icosphere(m, 2, 1.0);
  Euclidean e(m);
  const std::vector<Location<Mesh> > none;
  auto problems = SV::validate_input(m, none);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::NO_SITES);

  auto two = area_uniform_locations(m, 5, 1);
  two.push_back(two[2]);
  problems = SV::validate_input(m, two);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::COINCIDENT_SITES);
  CHECK(problems[0].element == 2);
  CHECK(problems[0].other == 5);
  CHECK(problems[0].message.find("sites 2 and 5") != std::string::npos);
  CHECK(SV::validate_input(m, two, SV::parameters::coincident_sites(SV::Coincident_sites::MERGE)).empty());

  std::vector<Point> far = { Point(0, 0, 1), Point(0, 0, 3) };
  problems = SV::validate_input(m, far, SV::parameters::max_site_distance(0.5));
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::SITE_TOO_FAR);
  CHECK(problems[0].element == 1);
  try
  {
    CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, far, SV::parameters::max_site_distance(0.5));
    FAIL("far site accepted");
  }
  catch(const SV::Site_too_far_error& x)
  {
    CHECK(x.site == 1);
    CHECK(x.distance == Approx(2.0).epsilon(1e-6));
  }

  std::vector<Point> nan = { Point(std::nan(""), 0, 0) };
  CHECK_THROWS_WITH((CGAL::Surface_voronoi_diagram<Mesh, Euclidean>(m, e, nan)), Catch::Contains("non-finite"));

  problems = SV::validate_input(m, nan);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::SITE_NOT_ON_MESH);

  // a descriptor that is not one of the mesh's: an Input_error in every build
  const std::vector<Mesh::Vertex_index> foreign = { Mesh::Vertex_index(1000000) };
  CHECK_THROWS_AS((CGAL::Surface_voronoi_diagram<Mesh, Euclidean>(m, e, foreign)), SV::Input_error);
  // a metric built on another mesh
  Mesh other = m;
  Euclidean e_other(other);
  CHECK_THROWS_WITH((CGAL::Surface_voronoi_diagram<Mesh, Euclidean>(m, e_other, area_uniform_locations(m, 3, 1))),
                    Catch::Contains("another mesh"));

  // a non-manifold vertex: two triangles sharing only a vertex (a bowtie)
  Mesh bowtie;
  const auto v0 = bowtie.add_vertex(Point(0, 0, 0)), v1 = bowtie.add_vertex(Point(1, 0, 0)), v2 = bowtie.add_vertex(Point(0, 1, 0));
  const auto v3 = bowtie.add_vertex(Point(-1, 0, 0)), v4 = bowtie.add_vertex(Point(0, -1, 0));
  bowtie.add_face(v0, v1, v2);
  bowtie.add_face(v0, v3, v4);
  REQUIRE(num_faces(bowtie) == 2);
  Euclidean eb(bowtie);
  std::vector<Mesh::Vertex_index> one = { v1 };
  problems = SV::validate_input(bowtie, one);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].kind == SV::Input_problem::NON_MANIFOLD_VERTEX);
  CHECK(problems[0].message.find("vertex 0 is non-manifold") != std::string::npos);
}

TEST_CASE("diagram: needles and caps (a 1 x 2e-9 rhombus) give finite locations and a diagram", "[diagram][numerics]")
{
  // Two valid triangles whose Gram determinant cancels to exactly 0: PMP's barycentric
  // coordinates are NaN on them (the program died of SIGFPE when they reached GMP).
  Mesh m;
  const auto a = m.add_vertex(Point(-0.5, 0, 0)), b = m.add_vertex(Point(0.5, 0, 0));
  const auto c = m.add_vertex(Point(0, 1e-9, 0)), d = m.add_vertex(Point(0, -1e-9, 0));
  m.add_face(a, b, c);
  m.add_face(b, a, d);
  namespace SVi = SV::internal;
  const SVi::Point_d p0(-0.5, 0, 0), p1(0.5, 0, 0), p2(0, 1e-9, 0);
  CHECK(SVi::is_needle(p0, p1, p2));
  const SVi::Point_d x(0.25, 2e-10, 0);
  const SVi::Barycentric bc = SVi::barycentric_coordinates(p0, p1, p2, x);
  for(double v : bc) REQUIRE(std::isfinite(v));
  CHECK(std::abs(bc[0] + bc[1] + bc[2] - 1) < 1e-12);
  // the point itself, to a small fraction of the triangle's height
  CHECK(std::sqrt(CGAL::squared_distance(SVi::point_at(p0, p1, p2, bc), x)) <= 1e-12);
  // a point on the long edge (of a cap whose other edges meet above it) gets an exact 0
  CHECK(SVi::barycentric_coordinates(p0, p1, p2, SVi::Point_d(-0.4, 0, 0))[2] == 0);
  // a well-shaped triangle keeps PMP's coordinates bit for bit
  const SVi::Point_d q0(0, 0, 0), q1(1, 0, 0), q2(0.3, 0.8, 0.1), y(0.4, 0.3, 0.05);
  CHECK(!SVi::is_needle(q0, q1, q2));
  CHECK(SVi::barycentric_coordinates(q0, q1, q2, y)
        == CGAL::Polygon_mesh_processing::barycentric_coordinates(q0, q1, q2, y, SVi::Double_kernel()));
  // coincident corners: no NaN either
  for(double v : SVi::barycentric_coordinates(q0, q0, q0, y)) CHECK(std::isfinite(v));

  // the rhombus is valid input: its faces are far above the degenerate threshold
  std::vector<Location<Mesh> > sites;
  sites.push_back(Location<Mesh>(*faces(m).begin(), {{ 0.2, 0.3, 0.5 }}));
  sites.push_back(Location<Mesh>(*std::next(faces(m).begin()), {{ 0.6, 0.1, 0.3 }}));
  sites.push_back(Location<Mesh>(*faces(m).begin(), {{ 0.7, 0.2, 0.1 }}));
  CHECK(SV::validate_input(m, sites).empty());
  Euclidean metric(m);
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, metric, sites);
  CHECK(vd.statistics().cells == 3);
  CHECK(vd.statistics().unreached_faces == 0);
  CHECK(std::abs(vd.statistics().surface_area - 1e-9) < 1e-18);
  Biharmonic biharmonic(m, SV::parameters::embedding_dimension(2));
  const CGAL::Surface_voronoi_diagram<Mesh, Biharmonic> bd(m, biharmonic, sites);
  CHECK(bd.statistics().cells == 3);
}

TEST_CASE("diagram: validate_input names degenerate needles and coordinates out of range", "[diagram][numerics]")
{
  auto two_faces = [](double height, double scale) {
    Mesh m;
    const auto a = m.add_vertex(Point(-0.5 * scale, 0, 0)), b = m.add_vertex(Point(0.5 * scale, 0, 0));
    const auto c = m.add_vertex(Point(0, height * scale, 0)), d = m.add_vertex(Point(0, -0.5 * scale, 0));
    m.add_face(a, b, c);
    m.add_face(b, a, d);
    return m;
  };
  const std::vector<Mesh::Vertex_index> site = { Mesh::Vertex_index(3) };
  // height 1e-9 of the unit edge: accepted; 1e-14 (area 5e-15 < 2^-44): degenerate
  CHECK(SV::validate_input(two_faces(1e-9, 1), site).empty());
  const auto needle = SV::validate_input(two_faces(1e-14, 1), site);
  REQUIRE(needle.size() == 1);
  CHECK(needle[0].kind == SV::Input_problem::ZERO_AREA_FACE);
  CHECK(needle[0].element == 0);
  CHECK(needle[0].message.find("degenerate") != std::string::npos);
  // the same shapes scaled by 2^300: coordinates out of range; by 2^-300: faces too small
  const auto big = SV::validate_input(two_faces(0.5, 0x1p300), site);
  REQUIRE(!big.empty());
  CHECK(big[0].kind == SV::Input_problem::COORDINATE_OUT_OF_RANGE);
  CHECK(big[0].message.find("2^200") != std::string::npos);
  const auto small = SV::validate_input(two_faces(0.5, 0x1p-300), site);
  REQUIRE(!small.empty());
  CHECK(small[0].kind == SV::Input_problem::ZERO_AREA_FACE);
  CHECK(small[0].message.find("too small") != std::string::npos);
  // the ends of the range are accepted
  CHECK(SV::validate_input(two_faces(0.5, 0x1p199), site).empty());
  CHECK(SV::validate_input(two_faces(0.5, 0x1p-199), site).empty());
}

} // namespace svd_test_surface_voronoi_diagram
