// The deprecated names of 0.1, kept for one release (the manual's "Migration from 0.1"): each
// old form must give exactly what its new form gives, so that moving from one to the other
// changes nothing. Every other test uses the new forms only.
//
// This file uses the deprecated declarations on purpose, so their warnings are silenced here,
// for the whole file and in no other: a deprecation warning from any other test or benchmark
// is one to act on.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

// The old header lloyd.h comes first, before any other header of the package: the
// using-declarations below compile only if lloyd.h alone still brings lloyd_relaxation() and
// its result type (the tests below call lloyd_relaxation() through it too).
#include <CGAL/Surface_voronoi_diagram/lloyd.h>
namespace svd_test_lloyd_header {
using CGAL::Surface_voronoi::lloyd_relaxation;
using CGAL::Surface_voronoi::Lloyd_result;
} // namespace svd_test_lloyd_header

#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Geodesic_metric.h>
#include <CGAL/Surface_voronoi_diagram/exceptions.h>
#include <CGAL/Surface_voronoi_diagram/options.h>
#include <CGAL/Surface_voronoi_diagram/refinement.h>
#include <CGAL/Surface_voronoi_diagram/sampling.h>
#include <test_meshes.h>

// The old draw header also warns when it is included, with #warning and #pragma message,
// which the pragma above cannot silence: CGAL's switch for that warning is set around this
// include only (CGAL/config.h has been read by now, so the deprecation attributes stay on).
// Only the old header is included, so CGAL::draw() below comes through it.
#define CGAL_NO_DEPRECATION_WARNINGS
#include <CGAL/Surface_voronoi_diagram/draw.h>
#undef CGAL_NO_DEPRECATION_WARNINGS

#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_deprecated {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace SVp = CGAL::Surface_voronoi::parameters;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef CGAL::Biharmonic_embedding<Mesh> Biharmonic;

namespace {

// the same partition, face piece by face piece, and the same cells, weights and statistics
template <class Diagram>
void require_same_diagram(const Diagram& a, const Diagram& b)
{
  const auto& pa = SV::internal::Diagram_access::data(a).partition.pieces;
  const auto& pb = SV::internal::Diagram_access::data(b).partition.pieces;
  REQUIRE(a.number_of_sites() == b.number_of_sites());
  REQUIRE(pa.size() == pb.size());
  std::size_t same_pieces = 0;
  for(std::size_t p = 0; p < pa.size(); ++p)
    same_pieces += (pa[p].site == pb[p].site && pa[p].vertices == pb[p].vertices);
  CHECK(same_pieces == pa.size());
  std::size_t same_cells = 0;
  for(std::size_t i = 0; i < a.number_of_sites(); ++i)
    same_cells += (a.cell_area(i) == b.cell_area(i) && a.number_of_pieces(i) == b.number_of_pieces(i)
                   && a.site_weight(i) == b.site_weight(i) && a.neighbors(i) == b.neighbors(i));
  CHECK(same_cells == a.number_of_sites());
  CHECK(a.unreached_area() == b.unreached_area());
  CHECK(a.statistics().broken_cells_before_repair == b.statistics().broken_cells_before_repair);
  CHECK(a.statistics().broken_cells == b.statistics().broken_cells);
  CHECK(a.statistics().repair_rounds == b.statistics().repair_rounds);
}

template <class Diagram>
std::vector<double> cell_areas(const Diagram& vd)
{
  std::vector<double> areas;
  for(std::size_t i = 0; i < vd.number_of_sites(); ++i) areas.push_back(vd.cell_area(i));
  return areas;
}

template <class Locations>
bool same_locations(const Locations& a, const Locations& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].first != b[i].first || a[i].second != b[i].second) return false;
  return true;
}

// what `f` writes to std::cerr
template <class F>
std::string captured_cerr(F f)
{
  std::ostringstream captured;
  std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
  f();
  std::cerr.rdbuf(old);
  return captured.str();
}

} // namespace

TEST_CASE("deprecated: Diagram_options with weights and GLOBAL_NEAREST is the named parameters' diagram", "[deprecated]")
{
  // a U-fold, where the restricted Voronoi diagram reaches through the gap and propagation
  // does not; weights of up to a fifth of the squared site spacing
  Mesh m;
  GEN::U_fold_options uo;
  uo.target_vertices = 2500;
  GEN::make_u_fold(m, uo);
  const auto sites = area_uniform_locations(m, 30, 8);
  const double spacing2 = CGAL::to_double(CGAL::Polygon_mesh_processing::area(m)) / double(sites.size());
  std::vector<double> weights(sites.size(), 0.);
  for(std::size_t i = 0; i < weights.size(); ++i) weights[i] = 0.1 * spacing2 * double(i % 3);
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;

  SV::Diagram_options o;
  o.weights = weights;
  o.candidates = SV::Candidate_selection::GLOBAL_NEAREST;
  const Diagram old_form(m, e, sites, o);
  const Diagram new_form(m, e, sites, SVp::site_weight_map(CGAL::make_property_map(weights),
                                      SVp::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST)));
  require_same_diagram(old_form, new_form);
  // both options were read: the weights and the candidate selection each change the diagram
  const Diagram unweighted(m, e, sites, SVp::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST));
  const Diagram propagated(m, e, sites, SVp::site_weight_map(CGAL::make_property_map(weights)));
  CHECK(cell_areas(old_form) != cell_areas(unweighted));
  CHECK(cell_areas(old_form) != cell_areas(propagated));

  // default options are the default named parameters; options and named parameters mix
  const Diagram old_default(m, e, sites, SV::Diagram_options());
  const Diagram new_default(m, e, sites);
  require_same_diagram(old_default, new_default);
  SV::Diagram_options weighted;
  weighted.weights = weights;
  auto none = m.add_property_map<Mesh::Edge_index, bool>("e:none", false).first;
  const Diagram old_mixed(m, e, sites, weighted, CGAL::parameters::edge_is_constrained_map(none));
  const Diagram new_mixed(m, e, sites, SVp::site_weight_map(CGAL::make_property_map(weights),
                                       CGAL::parameters::edge_is_constrained_map(none)));
  require_same_diagram(old_mixed, new_mixed);
  require_same_diagram(old_mixed, propagated);
}

TEST_CASE("deprecated: Diagram_options weights given together with an equal site_weight_map", "[deprecated]")
{
  // the deprecated options and a site_weight_map may both hold the weights: equal, they give
  // the diagram of either alone
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  std::vector<Mesh::Vertex_index> sites;
  for(std::size_t i = 3; i < num_vertices(m); i += 11) sites.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
  auto w = m.add_property_map<Mesh::Vertex_index, float>("v:weight", 0.f).first;
  for(Mesh::Vertex_index v : vertices(m)) w[v] = float(std::size_t(v) % 7) * 0.01f;
  SV::Diagram_options by_index;
  for(Mesh::Vertex_index v : sites) by_index.weights.push_back(double(w[v]));
  Euclidean e(m);
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Diagram;
  const Diagram from_map(m, e, sites, SVp::site_weight_map(w));
  auto none = m.add_property_map<Mesh::Edge_index, bool>("e:none", false).first;
  const Diagram both(m, e, sites, by_index, SVp::site_weight_map(w).edge_is_constrained_map(none));
  require_same_diagram(both, from_map);
  const Diagram plain(m, e, sites);
  CHECK(cell_areas(both) != cell_areas(plain));
}

TEST_CASE("deprecated: Diagram_options repair and max_site_distance are the named parameters", "[deprecated]")
{
  // many sites on a low-dimensional biharmonic embedding: cells come out in several pieces
  // (20 here), and the repair takes two rounds
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 40, 16);
  Biharmonic metric(m, SVp::embedding_dimension(3));
  const auto sites = area_uniform_locations(m, 200, 4);
  typedef CGAL::Surface_voronoi_diagram<Mesh> Diagram;
  const Diagram repaired(m, metric, sites);
  REQUIRE(repaired.statistics().broken_cells_before_repair > 0);
  REQUIRE(repaired.statistics().repair_rounds > 1);

  SV::Diagram_options no_repair;
  no_repair.repair = false;
  const Diagram old_unrepaired(m, metric, sites, no_repair);
  const Diagram new_unrepaired(m, metric, sites, SVp::repair_cells(false));
  require_same_diagram(old_unrepaired, new_unrepaired);
  CHECK(old_unrepaired.statistics().broken_cells > 0);

  SV::Diagram_options one_round;
  one_round.max_repair_rounds = 1;
  const Diagram old_one_round(m, metric, sites, one_round);
  const Diagram new_one_round(m, metric, sites, SVp::max_repair_rounds(1));
  require_same_diagram(old_one_round, new_one_round);
  CHECK(old_one_round.statistics().repair_rounds == 1);

  // a point site off the surface: too far for the option, as for the named parameter
  Mesh sphere;
  GEN::make_icosphere(sphere, 3, 1.0);
  Euclidean e(sphere);
  const std::vector<Point> points = { Point(0, 0, 1.2), Point(0, 0, -1), Point(1, 0, 0) };
  SV::Diagram_options near_only;
  near_only.max_site_distance = 0.1;
  typedef CGAL::Surface_voronoi_diagram<Mesh, Euclidean> Euclidean_diagram;
  CHECK_THROWS_AS(Euclidean_diagram(sphere, e, points, near_only), SV::Site_too_far_error);
  CHECK_THROWS_AS(Euclidean_diagram(sphere, e, points, SVp::max_site_distance(0.1)), SV::Site_too_far_error);
  SV::Diagram_options far_enough;
  far_enough.max_site_distance = 0.5;
  const Euclidean_diagram old_far(sphere, e, points, far_enough);
  const Euclidean_diagram new_far(sphere, e, points, SVp::max_site_distance(0.5));
  require_same_diagram(old_far, new_far);
}

TEST_CASE("deprecated: refine_for_sites(tm, sites, Refinement_options) is the named-parameter form", "[deprecated]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 10, 5);   // coarse: 50 vertices, refined for 200 sites
  const auto sites = area_uniform_locations(m, 200, 5);

  auto compare = [&](const auto& old_form, const SV::Refined_sites<Mesh>& new_form, const Mesh& new_mesh,
                     const Mesh::Property_map<Mesh::Face_index, Mesh::Face_index>& new_input_face) {
    static_assert(std::is_same<typename std::decay<decltype(old_form)>::type, SV::Refinement_result<Mesh, Point> >::value,
                  "the old form returns a Refinement_result");
    CHECK(!new_form.vertex_limit_reached);
    REQUIRE(num_vertices(old_form.mesh) == num_vertices(new_mesh));
    REQUIRE(num_faces(old_form.mesh) == num_faces(new_mesh));
    std::size_t same_points = 0, same_input_faces = 0;
    for(auto v : vertices(new_mesh)) same_points += (old_form.mesh.point(v) == new_mesh.point(v));
    for(auto f : faces(new_mesh)) same_input_faces += (old_form.input_face[f] == new_input_face[f]);
    CHECK(same_points == num_vertices(new_mesh));
    CHECK(same_input_faces == num_faces(new_mesh));
    CHECK(same_locations(old_form.sites, new_form.sites));
    CHECK(old_form.target_edge_length == new_form.target_edge_length);
    CHECK(old_form.edges_split == new_form.edges_split);
  };

  // the defaults
  const SV::Refinement_result<Mesh, Point> old_default = SV::refine_for_sites(m, sites);
  Mesh new_mesh;
  auto input_face = new_mesh.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input_face").first;
  const auto new_default = SV::refine_for_sites(m, sites, new_mesh, CGAL::parameters::default_values(),
                                                SVp::input_face_map(input_face));
  REQUIRE(new_default.edges_split > 0);
  compare(old_default, new_default, new_mesh, input_face);

  // other ratios: another refinement, the same in both forms
  SV::Refinement_options ro;
  ro.trigger_ratio = 1.0;
  ro.edge_length_ratio = 0.6;
  const auto old_ratios = SV::refine_for_sites(m, sites, ro);
  Mesh ratio_mesh;
  auto ratio_input_face = ratio_mesh.add_property_map<Mesh::Face_index, Mesh::Face_index>("f:input_face").first;
  const auto new_ratios = SV::refine_for_sites(m, sites, ratio_mesh,
                                               SVp::refinement_trigger_ratio(1.0, SVp::refinement_edge_length_ratio(0.6)),
                                               SVp::input_face_map(ratio_input_face));
  compare(old_ratios, new_ratios, ratio_mesh, ratio_input_face);
  CHECK(num_vertices(ratio_mesh) < num_vertices(new_mesh));

  // the vertex limit: the old form throws, the new one reports it
  SV::Refinement_options tiny;
  tiny.max_vertices = 100;
  CHECK_THROWS_AS(SV::refine_for_sites(m, sites, tiny), SV::Input_error);
  Mesh tiny_mesh;
  CHECK(SV::refine_for_sites(m, sites, tiny_mesh, SVp::refinement_max_vertices(100)).vertex_limit_reached);
}

TEST_CASE("deprecated: lloyd_relaxation(tm, metric, sites, iterations, options) is the named-parameter form", "[deprecated]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.4, 40, 16);
  Euclidean e(m);
  const auto start = area_uniform_locations(m, 40, 3);

  // the iterations alone (default options)
  const auto old_plain = SV::lloyd_relaxation(m, e, start, 3);
  const auto new_plain = SV::lloyd_relaxation(m, e, start, CGAL::parameters::number_of_iterations(3));
  REQUIRE(new_plain.energies.size() == 4);
  CHECK(old_plain.energies == new_plain.energies);
  CHECK(same_locations(old_plain.sites, new_plain.sites));
  CHECK(old_plain.kept_in_place == new_plain.kept_in_place);
  CHECK(!same_locations(new_plain.sites, start));   // the sites did move

  // with options: weights and the candidate selection reach every diagram of the relaxation
  std::vector<double> weights(start.size(), 0.);
  for(std::size_t i = 0; i < weights.size(); i += 4) weights[i] = 0.01;
  SV::Diagram_options o;
  o.weights = weights;
  o.candidates = SV::Candidate_selection::GLOBAL_NEAREST;
  const auto old_options = SV::lloyd_relaxation(m, e, start, 2, o);
  const auto new_options = SV::lloyd_relaxation(m, e, start,
      SVp::site_weight_map(CGAL::make_property_map(weights),
      SVp::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST, CGAL::parameters::number_of_iterations(2))));
  REQUIRE(new_options.energies.size() == 3);
  CHECK(old_options.energies == new_options.energies);
  CHECK(same_locations(old_options.sites, new_options.sites));
  CHECK(old_options.kept_in_place == new_options.kept_in_place);
  const auto unweighted = SV::lloyd_relaxation(m, e, start, SVp::candidate_selection(SV::Candidate_selection::GLOBAL_NEAREST,
                                                                                     CGAL::parameters::number_of_iterations(2)));
  CHECK(unweighted.energies != new_options.energies);   // the weights mattered
}

TEST_CASE("deprecated: random_sites and blue_noise_sites with a seed are the random_seed forms", "[deprecated]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  CHECK(same_locations(SV::random_sites(m, 200, 7u), SV::random_sites(m, 200, CGAL::parameters::random_seed(7))));
  CHECK(same_locations(SV::blue_noise_sites(m, 100, 7u), SV::blue_noise_sites(m, 100, CGAL::parameters::random_seed(7))));
  // the seed is passed on: another seed, other sites
  CHECK(!same_locations(SV::random_sites(m, 200, 8u), SV::random_sites(m, 200, CGAL::parameters::random_seed(7))));
  CHECK(!same_locations(SV::blue_noise_sites(m, 100, 8u), SV::blue_noise_sites(m, 100, CGAL::parameters::random_seed(7))));
}

TEST_CASE("deprecated: Geodesic_metric::set_sites(tm, sites) is set_sites(sites)", "[deprecated]")
{
  Mesh m;
  GEN::make_torus(m, 1.0, 0.35, 30, 12);
  const auto sites = area_uniform_locations(m, 5, 6);
  SV::Geodesic_metric<Mesh> old_form(m), new_form(m);
  old_form.set_sites(m, sites);
  new_form.set_sites(sites);
  std::size_t same = 0, positive = 0;
  for(std::size_t i = 0; i < sites.size(); ++i)
    for(auto v : vertices(m))
    {
      const double d = new_form.squared_distance(i, v);
      same += (old_form.squared_distance(i, v) == d);
      positive += (d > 0);
    }
  CHECK(same == sites.size() * num_vertices(m));
  CHECK(positive == sites.size() * num_vertices(m));
  const auto probes = area_uniform_locations(m, 20, 7);
  std::size_t same_inside = 0;
  for(const auto& l : probes) same_inside += (old_form.distance(2, l) == new_form.distance(2, l));
  CHECK(same_inside == probes.size());
}

TEST_CASE("deprecated: Surface_voronoi::draw() and the old draw header forward to CGAL::draw()", "[deprecated][draw]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  Euclidean e(m);
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, std::vector<Point>{Point(0.2, 0.2, 0), Point(0.8, 0.7, 0)});
#ifndef CGAL_USE_BASIC_VIEWER
  const std::string new_form = captured_cerr([&] { CGAL::draw(vd); });
  CHECK(new_form.find("CGAL_USE_BASIC_VIEWER") != std::string::npos);
  CHECK(captured_cerr([&] { SV::draw(vd); }) == new_form);
  CHECK(captured_cerr([&] { SV::draw(vd, "a title"); }) == captured_cerr([&] { CGAL::draw(vd, "a title"); }));
#endif
}

} // namespace svd_test_deprecated

#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
