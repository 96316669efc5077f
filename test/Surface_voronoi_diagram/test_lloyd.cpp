// Tests of CGAL/Surface_voronoi_diagram/lloyd_relaxation.h: centroidal relaxation and its energy.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <test_meshes.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_lloyd {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;

TEST_CASE("lloyd: the energy of the RVD with the Euclidean metric never increases", "[lloyd]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, 60, 24);
  Euclidean e(m);
  const auto r = SV::lloyd_relaxation(m, e, area_uniform_locations(m, 80, 3),
                                      SV::parameters::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST,
                                                                          CGAL::parameters::number_of_iterations(8)));
  REQUIRE(r.energies.size() == 9);
  for(std::size_t k = 1; k < r.energies.size(); ++k)
    CHECK(r.energies[k] <= r.energies[k - 1] * (1 + 1e-12));
  CHECK(r.energies.back() < 0.8 * r.energies.front());   // it really relaxes
}

TEST_CASE("lloyd: the energy is the integral of the squared distance", "[lloyd]")
{
  // one site on a flat unit square at its centre: the integral of |x - c|^2 is 1/6
  Mesh m;
  GEN::make_planar_grid(m, 11, 11, 1.0, 1.0);
  Euclidean e(m);
  std::vector<Point> one = { Point(0.5, 0.5, 0) };
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, one);
  CHECK(vd.energy() == Approx(1. / 6.).epsilon(1e-12));
  CHECK(CGAL::squared_distance(vd.cell_centroid(0), Point(0.5, 0.5, 0)) < 1e-24);
}

TEST_CASE("lloyd: Euclidean propagation and the biharmonic metric relax and stay valid", "[lloyd]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 3000;
  GEN::make_thin_lampshade(m, lo);
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 60, 9);
  const auto re = SV::lloyd_relaxation(m, e, start, CGAL::parameters::number_of_iterations(5));
  CHECK(re.energies.back() < re.energies.front());
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> final_e(m, e, re.sites);
  check_invariants(final_e);

  CGAL::Biharmonic_embedding<Mesh> b(m);
  const auto rb = SV::lloyd_relaxation(m, b, start, CGAL::parameters::number_of_iterations(5));
  CHECK(rb.energies.size() == 6);
  CGAL::Surface_voronoi_diagram<Mesh> final_b(m, b, rb.sites);
  check_invariants(final_b);
  // the biharmonic energy is reported, not minimized: the centroid is taken in space, which
  // is not the minimizer of the biharmonic energy; it stays finite and positive
  for(double x : rb.energies) CHECK((x > 0 && std::isfinite(x)));
}

namespace {

// Lloyd's diagrams measure their cells on the per-face cuts, without stitching them: the
// measures must be those of the stitched partition, up to rounding.
template <class Metric, class NP>
void check_cut_measures(const Mesh& m, Metric& metric, const std::vector<Location<Mesh> >& sites, const NP& np)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  const Diagram stitched(m, metric, sites, np);
  const Diagram on_cuts(m, metric, sites, SV::internal::cells_only(true, np));
  REQUIRE(stitched.statistics().broken_cells == 0);
  // the cuts decided here, so the measures do come from them, not from a partition
  REQUIRE(SV::internal::Diagram_access::data(on_cuts).measures.valid);
  REQUIRE(SV::internal::Diagram_access::data(on_cuts).partition.pieces.empty());
  const double area = stitched.surface_area();
  const double scale = std::sqrt(area);
  double total = 0;
  for(std::size_t i = 0; i < sites.size(); ++i)
  {
    CHECK(std::abs(on_cuts.cell_area(i) - stitched.cell_area(i)) <= 1e-12 * area);
    CHECK(std::sqrt(CGAL::squared_distance(on_cuts.cell_centroid(i), stitched.cell_centroid(i))) <= 1e-9 * scale);
    total += on_cuts.cell_area(i);
  }
  CHECK(total + on_cuts.unreached_area() == Approx(area).epsilon(1e-12));
  CHECK(on_cuts.energy() == Approx(stitched.energy()).epsilon(1e-10));
  CHECK(on_cuts.energy() > 0);
}

} // namespace

TEST_CASE("lloyd: cells measured on the cuts are those of the stitched partition", "[lloyd]")
{
  Mesh m;
  GEN::Lampshade_options lo;
  lo.target_vertices = 2500;
  GEN::make_thin_lampshade(m, lo);
  const auto sites = area_uniform_locations(m, 70, 5);
  SECTION("Euclidean")
  {
    Euclidean e(m);
    check_cut_measures(m, e, sites, CGAL::parameters::default_values());
  }
  SECTION("Euclidean power diagram")
  {
    Euclidean e(m);
    std::vector<double> weights(sites.size());
    for(std::size_t i = 0; i < weights.size(); ++i) weights[i] = 1e-4 * double(i % 7);
    check_cut_measures(m, e, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
  }
  SECTION("biharmonic")
  {
    CGAL::Biharmonic_embedding<Mesh> b(m);
    check_cut_measures(m, b, sites, CGAL::parameters::default_values());
  }
  SECTION("geodesic, weighted")
  {
    SV::Geodesic_metric<Mesh> g(m);
    std::vector<double> weights(sites.size());
    for(std::size_t i = 0; i < weights.size(); ++i) weights[i] = 1e-4 * double(i % 5);
    check_cut_measures(m, g, sites, SV::parameters::site_weight_map(CGAL::make_property_map(weights)));
  }
}

namespace {

// A Lloyd step's diagram starts its propagation from the candidates of the diagram before the
// sites moved (Propagation::run_from()). `exact`: sites moved by a Lloyd step, from which it
// must give the fresh diagram's candidates face by face and its measures bit for bit.
// Otherwise (sites moved anywhere, most previous candidates wrong) the propagation's order
// differs so much that a field may stop elsewhere, as after a propagation in blocks: it must
// still be a diagram of these sites (every cell one region, holding its site; the areas summing
// to the surface; every field a face holds held or dominated across each edge, where the
// repair banned none).
template <class Metric, class NP>
void check_started_from_previous(const Mesh& m, Metric& metric, const std::vector<Location<Mesh> >& before,
                                 const std::vector<Location<Mesh> >& after, const NP& np, bool exact)
{
  typedef CGAL::Surface_voronoi_diagram<Mesh, Metric> Diagram;
  // an update starts the propagation from the candidates before the sites moved
  Diagram started(m, metric, before, SV::internal::cells_only(true, np));
  for(std::size_t i = 0; i < after.size(); ++i) started.move_site(i, after[i]);
  started.update();
  const Diagram fresh(m, metric, after, SV::internal::cells_only(true, np));
  REQUIRE(fresh.statistics().broken_cells == 0);
  CHECK(started.statistics().broken_cells == 0);
  CHECK(started.statistics().unreached_faces == 0);
  // it did start from them: a fresh propagation's count of events is not the same
  CHECK(started.statistics().propagation_events != fresh.statistics().propagation_events);
  const auto& data = SV::internal::Diagram_access::data(started);
  const auto& a = SV::internal::Diagram_access::data(fresh).candidates;
  const auto& b = data.candidates;
  REQUIRE(a.size() == b.size());
  std::size_t other_lists = 0, open_edges = 0;
  for(std::size_t f = 0; f < a.size(); ++f)
  {
    bool same = a[f].size() == b[f].size();
    for(std::size_t k = 0; same && k < a[f].size(); ++k) same = a[f][k].site == b[f][k].site && a[f][k].value == b[f][k].value;
    other_lists += same ? 0 : 1;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = data.mesh->neighbors[f][k];
      if(g == SV::internal::Indexed_mesh<Mesh>::none || (!data.breaklines.empty() && data.breaklines.is_blocked(data.mesh->edges[f][k])))
        continue;
      for(const auto& x : b[f])
      {
        if(SV::internal::values_of(b[g], x.site)) continue;
        SV::internal::Candidate y(x.site, {{ 0., 0., 0. }});
        for(int c = 0; c < 3; ++c) y.value[c] = data.embedding->value(x.site, data.mesh->triangles[g][c]);
        bool dominated = false;
        for(const auto& z : b[g]) dominated = dominated || SV::internal::dominates(z, y);
        open_edges += dominated ? 0 : 1;
      }
    }
  }
  // (the repair bans fields from the faces of a cell's pieces cut off from its site)
  if(started.statistics().broken_cells_before_repair == 0) CHECK(open_edges == 0);
  const double area = fresh.surface_area();
  double total = 0;
  for(std::size_t i = 0; i < after.size(); ++i)
  {
    if(exact)
    {
      CHECK(started.cell_area(i) == fresh.cell_area(i));
      CHECK(started.cell_centroid(i) == fresh.cell_centroid(i));
    }
    CHECK(started.cell_area(i) > 0);
    CHECK(SV::internal::values_of(b[data.sites[i].face], static_cast<std::uint32_t>(i)) != nullptr);
    total += started.cell_area(i);
  }
  if(exact) CHECK(other_lists == 0);
  CHECK(total == Approx(area).epsilon(1e-12));
}

} // namespace

TEST_CASE("lloyd: a diagram started from the one before its sites moved is the diagram computed afresh", "[lloyd]")
{
  SECTION("thin lampshade, Euclidean, biharmonic and a power diagram")
  {
    Mesh m;
    GEN::Lampshade_options lo;
    lo.target_vertices = 3000;
    GEN::make_thin_lampshade(m, lo);
    const auto before = area_uniform_locations(m, 80, 4);
    Euclidean e(m);
    const auto moved = SV::lloyd_relaxation(m, e, before, CGAL::parameters::number_of_iterations(1)).sites;
    check_started_from_previous(m, e, before, moved, CGAL::parameters::default_values(), true);
    check_started_from_previous(m, e, before, area_uniform_locations(m, 80, 5), CGAL::parameters::default_values(), false);
    std::vector<double> weights(before.size());
    for(std::size_t i = 0; i < weights.size(); ++i) weights[i] = 2e-4 * double(i % 7);
    check_started_from_previous(m, e, before, moved, SV::parameters::site_weight_map(CGAL::make_property_map(weights)), true);
    CGAL::Biharmonic_embedding<Mesh> b(m);
    const auto moved_b = SV::lloyd_relaxation(m, b, before, CGAL::parameters::number_of_iterations(1)).sites;
    check_started_from_previous(m, b, before, moved_b, CGAL::parameters::default_values(), true);
    check_started_from_previous(m, b, before, area_uniform_locations(m, 80, 6), CGAL::parameters::default_values(), false);
  }
  SECTION("a breakline with sites on it")
  {
    Mesh m;
    GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);   // spacing 0.05
    auto line = m.add_property_map<Mesh::Edge_index, bool>("e:breakline", false).first;
    for(auto ed : edges(m))
    {
      const Point p = m.point(source(halfedge(ed, m), m)), q = m.point(target(halfedge(ed, m), m));
      line[ed] = std::abs(p.x() - 0.5) < 1e-9 && std::abs(q.x() - 0.5) < 1e-9 && p.y() < 0.7 + 1e-9 && q.y() < 0.7 + 1e-9;
    }
    std::vector<Point> points = { Point(0.5, 0.125, 0), Point(0.5, 0.425, 0) };   // on the line, inside edges
    for(const auto& l : area_uniform_locations(m, 30, 8)) points.push_back(point_of(l, m));
    Euclidean e(m);
    const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> locate(m, e, points);
    std::vector<Location<Mesh> > before;
    for(std::size_t i = 0; i < points.size(); ++i) before.push_back(locate.site_location(i));
    const auto np = CGAL::parameters::edge_is_constrained_map(line);
    const auto moved = SV::lloyd_relaxation(m, e, before, SV::parameters::first_moving_site(2, np.number_of_iterations(1))).sites;
    REQUIRE(!SV::internal::Diagram_access::data(CGAL::Surface_voronoi_diagram<Mesh, Euclidean>(m, e, moved, np)).breakline_site_faces.empty());
    check_started_from_previous(m, e, before, moved, np, true);
    check_started_from_previous(m, e, before, area_uniform_locations(m, 32, 9), np, false);
  }
}

TEST_CASE("lloyd: a vertex density map draws the sites where it is high", "[lloyd][density]")
{
  Mesh m;
  GEN::make_planar_grid(m, 21, 21, 1.0, 1.0);
  std::vector<double> density(num_vertices(m));
  for(auto v : vertices(m)) density[v.idx()] = (m.point(v).x() > 0.5) ? 3. : 1.;
  auto density_map = m.add_property_map<Mesh::Vertex_index, double>("v:test_density", 0.).first;
  for(auto v : vertices(m)) density_map[v] = density[v.idx()];
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 120, 11);
  auto right_fraction = [&](const std::vector<Location<Mesh> >& sites) {
    std::size_t right = 0;
    for(const auto& l : sites) right += (point_of(l, m).x() > 0.5);
    return double(right) / double(sites.size());
  };
  // Lloyd moves sites across the surface slowly: from area-uniform sites the density draws
  // them to the right...
  const auto drawn = SV::lloyd_relaxation(m, e, start, SV::parameters::vertex_density_map(density_map,
                                          CGAL::parameters::number_of_iterations(40)));
  CHECK(right_fraction(start) < 0.6);
  CHECK(right_fraction(drawn.sites) > right_fraction(start) + 0.05);
  // ...and from sites drawn with that density (3/4 on the right: three sites per unit area
  // for one), it keeps them there, where relaxing without it spreads them out
  const auto dense = SV::random_sites(m, 120, SV::parameters::vertex_density_map(density_map, CGAL::parameters::random_seed(2)));
  const auto kept = SV::lloyd_relaxation(m, e, dense, SV::parameters::vertex_density_map(density_map,
                                         CGAL::parameters::number_of_iterations(40)));
  const auto spread = SV::lloyd_relaxation(m, e, dense, CGAL::parameters::number_of_iterations(40));
  CHECK(right_fraction(kept.sites) > 0.68);
  CHECK(right_fraction(kept.sites) < 0.82);
  CHECK(right_fraction(spread.sites) < right_fraction(kept.sites) - 0.05);

  // a uniform density of any level moves the sites as no density does
  const auto uniform = SV::lloyd_relaxation(m, e, start, SV::parameters::vertex_density_map(
      CGAL::Constant_property_map<Mesh::Vertex_index, double>(7.), CGAL::parameters::number_of_iterations(3)));
  const auto none = SV::lloyd_relaxation(m, e, start, CGAL::parameters::number_of_iterations(3));
  for(std::size_t i = 0; i < start.size(); ++i)
    CHECK(CGAL::squared_distance(point_of(uniform.sites[i], m), point_of(none.sites[i], m)) < 1e-20);
}

TEST_CASE("lloyd: a density map that is negative, not a number or zero everywhere is an error", "[lloyd][density]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 5, 1);
  for(const double bad : { -1., std::numeric_limits<double>::quiet_NaN(), 0. })
  {
    INFO("density " << bad);
    auto density = m.add_property_map<Mesh::Vertex_index, double>("v:bad_density", bad == 0. ? 0. : 1.).first;
    density[*vertices(m).begin()] = bad;
    CHECK_THROWS_AS(SV::lloyd_relaxation(m, e, start, SV::parameters::vertex_density_map(density)), SV::Input_error);
    m.remove_property_map(density);
  }
}

TEST_CASE("lloyd: the sites before first_moving_site stay where they are, the others relax", "[lloyd]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, 60, 24);
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 80, 5);
  const std::size_t fixed = 20;
  const auto r = SV::lloyd_relaxation(m, e, start, SV::parameters::first_moving_site(fixed, CGAL::parameters::number_of_iterations(4)));
  REQUIRE(r.sites.size() == start.size());
  std::size_t moved = 0;
  for(std::size_t i = 0; i < start.size(); ++i)
  {
    if(i < fixed)
    {
      CHECK(r.sites[i].first == start[i].first);
      CHECK(r.sites[i].second == start[i].second);
    }
    else moved += (point_of(r.sites[i], m) != point_of(start[i], m));
  }
  CHECK(moved == start.size() - fixed);
  CHECK(r.energies.back() < r.energies.front());
}

TEST_CASE("lloyd: a centroid goes to the nearest point of the faces its cell reaches", "[lloyd]")
{
  // oracle: the nearest point by brute force over the faces where the site is a candidate
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, 48, 20);
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 60, 11);
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> before(m, e, start);
  const auto r = SV::lloyd_relaxation(m, e, start, CGAL::parameters::number_of_iterations(1));
  REQUIRE(r.kept_in_place == 0);
  const auto& data = SV::internal::Diagram_access::data(before);
  std::vector<std::vector<Mesh::Face_index> > faces_of(start.size());
  for(std::size_t f = 0; f < data.candidates.size(); ++f)
    for(const auto& x : data.candidates[f]) faces_of[x.site].push_back(data.mesh->face_handles[f]);
  for(std::size_t i = 0; i < start.size(); ++i)
  {
    faces_of[i].push_back(start[i].first);
    const Point c = before.cell_centroid(i);
    double nearest = std::numeric_limits<double>::infinity();
    for(Mesh::Face_index f : faces_of[i])
    {
      const auto h = m.halfedge(f);
      const K::Triangle_3 t(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
      nearest = (std::min)(nearest, CGAL::squared_distance(c, t));
    }
    const double ours = CGAL::squared_distance(c, point_of(r.sites[i], m));
    CHECK(std::find(faces_of[i].begin(), faces_of[i].end(), r.sites[i].first) != faces_of[i].end());
    CHECK(ours <= nearest * (1 + 1e-9) + 1e-24);
    CHECK(ours >= nearest * (1 - 1e-9) - 1e-24);
    CHECK(ours <= CGAL::squared_distance(c, point_of(start[i], m)) * (1 + 1e-9) + 1e-24);
  }
}

TEST_CASE("lloyd: a site stays on its side of a thin wall", "[lloyd]")
{
  // On a pot whose wall is thinner than the cells are curved, the centroid of a cell on the
  // outer wall lies inside the wall, nearer the inner side: the nearest point of the whole
  // surface would move the site through the wall (about half of them here).
  Mesh m;
  GEN::Pot_options po;
  po.target_vertices = 6000;
  po.thickness = 0.001;
  GEN::make_thin_pot(m, po);
  const double R = 1. / 3., H = 1. / 3., t = po.thickness;   // the pot's proportions at size 1
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 100, 2);
  const CGAL::Surface_voronoi_diagram<Mesh, Euclidean> before(m, e, start);
  const auto r = SV::lloyd_relaxation(m, e, start, CGAL::parameters::number_of_iterations(1));
  // 1 outer wall, -1 inner
  auto side = [&](const Point& p) { return std::sqrt(p.x() * p.x() + p.y() * p.y()) > R - t / 2 ? 1 : -1; };
  // the sites whose cell lies on one side of the vertical wall (not over the rim or the bottom)
  const auto& data = SV::internal::Diagram_access::data(before);
  std::vector<int> cell_side(start.size(), 2);   // 2: no face yet, 0: both sides or off the wall
  for(std::size_t f = 0; f < data.candidates.size(); ++f)
  {
    const auto& a = data.mesh->corner(f, 0);
    const auto& b = data.mesh->corner(f, 1);
    const auto& c = data.mesh->corner(f, 2);
    const bool on_wall = (std::min)({ a.z(), b.z(), c.z() }) > 0.1 * H && (std::max)({ a.z(), b.z(), c.z() }) < 0.9 * H;
    const int s = on_wall ? side(Point((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3, 0)) : 0;
    for(const auto& x : data.candidates[f]) cell_side[x.site] = (cell_side[x.site] == 2 || cell_side[x.site] == s) ? s : 0;
  }
  std::size_t on_one_side = 0;
  for(std::size_t i = 0; i < start.size(); ++i)
  {
    if(cell_side[i] == 0 || cell_side[i] == 2) continue;
    ++on_one_side;
    CHECK(side(point_of(r.sites[i], m)) == cell_side[i]);
  }
  CHECK(on_one_side >= 20);
}

} // namespace svd_test_lloyd
