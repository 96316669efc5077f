// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Sites added until the dual triangulation is a valid mesh: where the cells lack the
// closed-ball property, the widest cell involved gets a new site at its point farthest from
// its own site; a flipped dual triangle, one on the rim its fold crosses (or at its Voronoi
// vertex). The sites that cut cells are relaxed among the given ones, which stay in place.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_VALID_DUAL_SITES_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_VALID_DUAL_SITES_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/dual_triangulation.h>
#include <CGAL/Surface_voronoi_diagram/dual_validity.h>
#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Diagram_data.h>
#include <CGAL/Surface_voronoi_diagram/internal/Double_kernel.h>
#include <CGAL/Surface_voronoi_diagram/internal/Local_site_spacing.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// The default of the named parameter `maximum_number_of_added_sites` of
/// `add_sites_for_valid_dual()` and `add_sites_for_valid_geodesic_dual()` for `given` sites: a
/// quarter of them, and at least 64. A caller that sizes something by the sites there may be
/// (a weight map, a memory budget) asks it.
inline std::size_t default_maximum_number_of_added_sites(std::size_t given)
{
  return (std::max)(std::size_t(64), given / 4);
}

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// What `add_sites_for_valid_dual()` did.
/// \tparam TriangleMesh the mesh type of the sites
template <class TriangleMesh>
struct Valid_dual_result
{
  /// the given sites, in place and in their order, then the sites added
  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites;
  /// the number of sites added (the last ones of `sites`)
  std::size_t sites_added = 0;
  /// the rounds of additions made
  std::size_t rounds = 0;
  /// whether it stopped, the dual still not valid, with no cell to cut: what is wrong is the
  /// triangulation's topology alone (the sites are too few for the surface's genus, or a
  /// component holds no site)
  bool nothing_to_cut = false;
  /// whether it stopped, the dual still not valid, because every site it would add fell
  /// beside an existing one (a fold at a point where the surface is not smooth, such as the
  /// tip of a cone, that no site nearby resolves)
  bool no_room_for_sites = false;
  /// whether it stopped (with `stop_on_coarse_mesh`), the dual still not valid, because sites
  /// it added crowd closer than the mesh resolves: the caller refines the mesh for `sites`
  /// (`refine_for_sites()` with `refinement_local_spacing`) and goes on there
  bool mesh_too_coarse = false;
  /// the validity of the dual of the final sites; `validity.is_valid()` tells whether a valid
  /// dual was reached
  Dual_validity validity;
};

namespace internal {

// A point of (or on the border of) face f, as a location of f: clamped and normalized, so
// that rounding does not step outside the face.
template <class TriangleMesh>
CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>
location_in_face(const Indexed_mesh<TriangleMesh>& mesh, std::size_t f, const Point_d& p)
{
  return { mesh.face_handles[f], clamped_barycentric(mesh.barycentric_coordinates(f, p)) };
}

// Per site, the centroid of its piece farthest from it (Euclidean), as a location of the
// mesh, and that distance: where a cell that wraps around a rim or a limb reaches farthest.
template <class TriangleMesh, class Diagram>
void farthest_pieces(const Diagram& diagram,
                     std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >& where,
                     std::vector<double>& distance)
{
  const auto& data = Diagram_access::data(diagram);
  const auto& mesh = *data.mesh;
  const std::size_t n = diagram.number_of_sites();
  std::vector<Point_d> site(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto& t = mesh.triangles[data.sites[i].face];
    const auto& b = data.sites[i].barycentric;
    site[i] = CGAL::barycenter(mesh.points[t[0]], b[0], mesh.points[t[1]], b[1], mesh.points[t[2]], b[2]);
  }
  where.assign(n, CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>());
  distance.assign(n, -1.);
  for(const Partition::Piece& piece : data.partition.pieces)
  {
    if(piece.site >= n || piece.vertices.empty()) continue;
    double x = 0, y = 0, z = 0;
    for(std::size_t v : piece.vertices)
    {
      const Point_d& p = data.partition.vertices[v].point;
      x += p.x(); y += p.y(); z += p.z();
    }
    const double k = double(piece.vertices.size());
    const Point_d c(x / k, y / k, z / k);
    const double d = CGAL::squared_distance(c, site[piece.site]);
    if(d <= distance[piece.site]) continue;
    distance[piece.site] = d;
    where[piece.site] = location_in_face(mesh, piece.face, c);
  }
}

// The Voronoi vertices where exactly three cells meet, as locations of the mesh, keyed by
// their three sites in increasing order (the first such vertex of each triple, in piece order).
template <class TriangleMesh, class Diagram>
std::map<std::array<std::size_t, 3>, CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> >
voronoi_vertex_locations(const Diagram& diagram)
{
  const auto& data = Diagram_access::data(diagram);
  const auto& mesh = *data.mesh;
  const Partition& partition = data.partition;
  const std::size_t n = diagram.number_of_sites();
  // the sites around each partition vertex (up to four), and a piece holding it
  std::vector<std::array<std::size_t, 4> > around(partition.vertices.size());
  std::vector<std::uint8_t> count(partition.vertices.size(), 0);
  std::vector<std::size_t> piece_of(partition.vertices.size(), no_site);
  for(std::size_t p = 0; p < partition.pieces.size(); ++p)
  {
    const Partition::Piece& piece = partition.pieces[p];
    if(piece.site >= n) continue;
    for(std::size_t v : piece.vertices)
    {
      if(piece_of[v] == no_site) piece_of[v] = p;
      // four distinct sites are enough to rule a vertex out (only those of three are kept)
      std::array<std::size_t, 4>& a = around[v];
      if(count[v] == 4 || std::find(a.begin(), a.begin() + count[v], piece.site) != a.begin() + count[v]) continue;
      a[count[v]++] = piece.site;
    }
  }
  std::map<std::array<std::size_t, 3>, CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > out;
  for(std::size_t v = 0; v < partition.vertices.size(); ++v)
  {
    if(count[v] != 3) continue;
    std::array<std::size_t, 3> key = {{ around[v][0], around[v][1], around[v][2] }};
    std::sort(key.begin(), key.end());
    out.emplace(key, location_in_face(mesh, partition.pieces[piece_of[v]].face, partition.vertices[v].point));
  }
  return out;
}

// A dual triangle facing against the surface at its Voronoi vertex, where one of its sites
// lies on the other side of a thin part (its cell wraps around the rim to reach the vertex),
// folds the remesh over that rim: no site resolves the rim. The remedy is a site on the rim
// itself, where that cell's faces turn from facing along the vertex's side to facing against
// it: the point of such an edge nearest to the vertex. Returns false when the triangle has no
// site across a rim (then the surface bends more than its sites resolve, and the vertex
// itself takes the new site).
template <class TriangleMesh, class Diagram>
bool rim_site_of_flip(const Diagram& diagram, const std::array<std::size_t, 3>& triangle,
                      const CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>& vertex,
                      CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>& rim)
{
  const auto& data = Diagram_access::data(diagram);
  const auto& mesh = *data.mesh;
  auto normal = [&](std::size_t f) {
    return CGAL::cross_product(mesh.corner(f, 1) - mesh.corner(f, 0), mesh.corner(f, 2) - mesh.corner(f, 0));
  };
  const std::size_t fv = get(mesh.face_index, vertex.first);
  const auto up = normal(fv);
  const Point_d at = mesh.point_at(fv, vertex.second);
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t s : triangle)
  {
    if(normal(data.sites[s].face) * up >= 0) continue;
    // the faces the cell of s reaches
    std::vector<std::size_t> cell_faces;
    for(const Partition::Piece& piece : data.partition.pieces)
      if(piece.site == s) cell_faces.push_back(piece.face);
    std::sort(cell_faces.begin(), cell_faces.end());
    cell_faces.erase(std::unique(cell_faces.begin(), cell_faces.end()), cell_faces.end());
    for(std::size_t f : cell_faces)
    {
      if(normal(f) * up < 0) continue;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = mesh.neighbors[f][k];
        if(g == Indexed_mesh<TriangleMesh>::none || normal(g) * up >= 0
           || !std::binary_search(cell_faces.begin(), cell_faces.end(), g)) continue;
        // the point of edge k of f nearest to the vertex
        const Point_d& a = mesh.points[mesh.triangles[f][k]];
        const Point_d& b = mesh.points[mesh.triangles[f][(k + 1) % 3]];
        const auto ab = b - a;
        const double len2 = ab * ab;
        const double u = len2 > 0 ? (std::min)(1., (std::max)(0., ((at - a) * ab) / len2)) : 0.;
        const Point_d p = a + u * ab;
        const double d = CGAL::squared_distance(p, at);
        if(d < best)
        {
          best = d;
          rim = location_in_face(mesh, f, p);
        }
      }
    }
  }
  return best < std::numeric_limits<double>::infinity();
}

// Whether a site from index `first_added` on lies in a face with an edge longer than 1.5
// times its distance to the nearest neighbour (at least a sixteenth of the mean spacing): the
// mesh cannot resolve the sites there (see `stop_on_coarse_mesh`). Neighbours as the
// refinement's local rule has them (Local_site_spacing.h): a site whose face faces away,
// across a thin wall, is none, so that a refinement by that rule does resolve what this finds.
template <class Diagram>
bool added_sites_crowd_the_mesh(const Diagram& diagram, std::size_t first_added)
{
  const auto& data = Diagram_access::data(diagram);
  const auto& mesh = *data.mesh;
  const std::size_t n = data.sites.size();
  if(first_added >= n) return false;
  std::vector<Point_d> at(n);
  std::vector<Vector_d> normal(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t f = data.sites[i].face;
    at[i] = mesh.point_at(f, data.sites[i].barycentric);
    normal[i] = CGAL::cross_product(mesh.corner(f, 1) - mesh.corner(f, 0), mesh.corner(f, 2) - mesh.corner(f, 0));
  }
  const double floor = Local_site_spacing::floor_ratio * std::sqrt(mesh.total_area / double(n));
  for(std::size_t i = first_added; i < n; ++i)
  {
    double nearest2 = std::numeric_limits<double>::infinity();
    for(std::size_t j = 0; j < n; ++j)
      if(j != i && Local_site_spacing::are_neighbours(normal[i], normal[j])) nearest2 = (std::min)(nearest2, CGAL::squared_distance(at[i], at[j]));
    const double spacing = (std::max)(std::sqrt(nearest2), floor);
    const std::size_t f = data.sites[i].face;
    for(int k = 0; k < 3; ++k)
      if(CGAL::squared_distance(mesh.corner(f, k), mesh.corner(f, (k + 1) % 3)) > CGAL::square(1.5 * spacing)) return true;
  }
  return false;
}

} // namespace internal

/// \ingroup PkgSurfaceVoronoiDiagramSites
/// Adds sites until the dual triangulation (`dual_triangulation()`) is a valid mesh of the
/// surface (`Dual_validity::is_valid()`), or until it may add no more.
///
/// Each round builds the diagram and checks its dual. Where the cells lack the closed-ball
/// property (a cell that is not a disk, two cells sharing several arcs, three meeting at
/// several Voronoi vertices), the widest cell involved (the one whose farthest piece is
/// farthest from its site) gets a new site at that piece: a cell wrapping around a rim or a
/// limb is cut there. Each cell gets one new site a round. A flipped dual triangle (see
/// `Dual_validity::flipped_triangles`) folds over a thin part when one of its cells reaches
/// around a rim to its Voronoi vertex: it gets a new site on that rim (the point nearest to
/// the vertex of an edge where the cell's faces turn from facing along the vertex's side to
/// facing against it); with no such rim, the surface bends more than its sites resolve, and
/// the new site is at the Voronoi vertex. No new site is placed closer than a tenth of the
/// mean spacing of the sites to another (it would make a sliver cell); where neither the rim
/// nor the vertex has room (a rim crowded with sites already), the widest cell of the
/// triangle is cut instead. A round that can place none ends the loop
/// (`no_room_for_sites`). The sites that cut cells are then relaxed by Lloyd steps in which
/// the given sites, and those on rims and Voronoi vertices, stay in place.
/// The given sites keep their positions and indices; the added ones follow them, those that
/// stay in place first (their order may change from round to round).
///
/// \tparam ConcurrencyTag the concurrency tag of the diagrams built; default `CGAL::Sequential_tag`
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam Metric a model of `SurfaceVoronoiEmbedding` or of `SurfaceVoronoiLazyMetric`
/// \param tm the mesh
/// \param metric the metric, built on `tm`
/// \param sites the given sites
/// \param np an optional sequence of named parameters: those of the diagram's constructor
///        (they apply to every diagram built) and the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_number_of_added_sites}
///     \cgalParamDescription{how many sites may be added at most}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{a quarter of the given sites, and at least 64}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the Lloyd steps of the added sites after each round}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{Surface_voronoi::parameters::stop_on_coarse_mesh}
///     \cgalParamDescription{whether to return (with `mesh_too_coarse`) once an added site lies
///       in a face with an edge longer than 1.5 times its distance to the nearest site whose
///       face does not face away from its own (at least a sixteenth of the mean spacing): a
///       metric sampled at vertices, such as
///       `Geodesic_metric`, cannot tell such sites apart, and the sites added there would only
///       pile up (a thin bar meshed with long needles). The caller refines the mesh for the
///       sites (`refine_for_sites()` with `refinement_local_spacing`), builds the metric on it
///       and calls again, the sites so far given.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sites, how many were added, and the validity of their dual
/// \pre the preconditions of the diagram's constructor hold for `sites`
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Metric, typename CGAL_NP_TEMPLATE_PARAMETERS>
Valid_dual_result<TriangleMesh>
add_sites_for_valid_dual(const TriangleMesh& tm, Metric& metric,
                         std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> > sites,
                         const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Location;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef CGAL::Surface_voronoi_diagram<TriangleMesh, Metric, VPM, Geom_traits, ConcurrencyTag> Diagram;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const std::size_t given = sites.size();
  const std::size_t max_added = choose_parameter(get_parameter(np, internal_np::maximum_number_of_added_sites),
                                                 default_maximum_number_of_added_sites(given));
  const std::size_t relax = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(3));
  const bool stop_when_coarse = choose_parameter(get_parameter(np, internal_np::stop_on_coarse_mesh), false);
  // rounds beyond the budget's need: each adds at least one site
  const std::size_t max_rounds = 64;

  Valid_dual_result<TriangleMesh> result;
  std::size_t first_moving = given;
  // one diagram, updated after each round as its sites change
  Diagram diagram(tm, metric, sites, np);
  for(;;)
  {
    std::vector<typename Diagram::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    dual_triangulation(diagram, std::back_inserter(points), std::back_inserter(triangles));
    result.validity = validate_dual_triangulation(diagram, points, triangles);
    if(result.validity.is_valid() || result.sites_added >= max_added || result.rounds >= max_rounds) break;
    if(stop_when_coarse && internal::added_sites_crowd_the_mesh(diagram, given))
    {
      result.mesh_too_coarse = true;
      break;
    }

    // the cells to cut: for each defect, its widest cell
    std::vector<Location> farthest;
    std::vector<double> reach;
    internal::farthest_pieces<TriangleMesh>(diagram, farthest, reach);
    std::vector<std::uint8_t> cut(sites.size(), 0);
    // the cell among `cells` reaching farthest from its site, or none if none reaches at all
    auto widest_of = [&](std::initializer_list<std::size_t> cells) {
      const std::size_t best = *std::max_element(cells.begin(), cells.end(),
                                                 [&](std::size_t a, std::size_t b) { return reach[a] < reach[b]; });
      return reach[best] > 0 ? best : internal::no_site;
    };
    auto widest = [&](std::initializer_list<std::size_t> cells) {
      const std::size_t best = widest_of(cells);
      if(best != internal::no_site) cut[best] = 1;
    };
    const Dual_validity& v = result.validity;
    for(std::size_t s : v.cells_not_disks) widest({ s });
    for(const auto& p : v.pairs_in_several_arcs) widest({ p.first, p.second });
    for(const auto& t : v.triples_at_several_vertices) widest({ t[0], t[1], t[2] });
    // a new site where one already is would merge into it and change nothing; one placed on a
    // rim or at a Voronoi vertex right beside another (closer than a tenth of the mean
    // spacing) would make a sliver cell where the fold it is for stays (at a point where the
    // surface is not smooth), so it is not placed either
    const auto& data = internal::Diagram_access::data(diagram);
    const auto& mesh = *data.mesh;
    const double same = CGAL::square(1e-9 * mesh.bbox_diagonal);
    const double beside = 0.01 * mesh.total_area / double(sites.size());
    std::vector<internal::Point_d> taken;
    for(const auto& s : data.sites) taken.push_back(mesh.point_at(s.face, s.barycentric));
    // new sites that cut a cell are relaxed with the others added before; those placed on a
    // rim or at a Voronoi vertex stay there, as Lloyd would pull them back off the rim
    std::vector<Location> moving, staying;
    std::size_t tried = 0;
    auto add = [&](const Location& l, std::vector<Location>& to) {
      ++tried;
      if(result.sites_added + moving.size() + staying.size() >= max_added) return true;
      const internal::Point_d p = mesh.point_at(get(mesh.face_index, l.first), l.second);
      const double tolerance = (&to == &staying) ? beside : same;
      for(const internal::Point_d& q : taken)
        if(CGAL::squared_distance(p, q) <= tolerance) return false;
      taken.push_back(p);
      to.push_back(l);
      return true;
    };
    for(std::size_t s = 0; s < cut.size(); ++s)
      if(cut[s]) add(farthest[s], moving);
    // a flipped triangle gets a site on the rim its fold crosses, or else at its Voronoi
    // vertex, where the surface bends more than its three sites resolve; its widest cell is
    // cut if no vertex of three cells makes it, or if the rim and the vertex are both crowded
    // (the planter pot's rim, where the two sheets are 7e-5 spacings apart, had sites beside
    // both, and the loop ended there with the fold left)
    if(!v.flipped_triangle_indices.empty())
    {
      const auto vertices = internal::voronoi_vertex_locations<TriangleMesh>(diagram);
      for(std::size_t k : v.flipped_triangle_indices)
      {
        std::array<std::size_t, 3> key = triangles[k];
        std::sort(key.begin(), key.end());
        const auto at = vertices.find(key);
        Location rim;
        if(at != vertices.end()
           && ((internal::rim_site_of_flip<TriangleMesh>(diagram, key, at->second, rim) && add(rim, staying))
               || add(at->second, staying)))
          continue;
        const std::size_t best = widest_of({ key[0], key[1], key[2] });
        if(best != internal::no_site) add(farthest[best], moving);
      }
    }
    if(moving.empty() && staying.empty())
    {
      (tried == 0 ? result.nothing_to_cut : result.no_room_for_sites) = true;
      break;
    }
    result.sites_added += moving.size() + staying.size();
    ++result.rounds;
    // the given sites, the added ones that stay, then those that move
    sites.insert(sites.begin() + std::ptrdiff_t(first_moving), staying.begin(), staying.end());
    first_moving += staying.size();
    sites.insert(sites.end(), moving.begin(), moving.end());
    if(relax > 0)
      sites = lloyd_relaxation<ConcurrencyTag>(tm, metric, sites,
                  parameters::first_moving_site(first_moving, np).number_of_iterations(relax)).sites;
    // the sites as now ordered, with the weights the map gives them at their new indices
    for(std::size_t i = 0; i < sites.size(); ++i)
    {
      if(i >= diagram.number_of_sites()) diagram.insert_site(sites[i]);
      else if(!(diagram.site_location(i) == sites[i])) diagram.move_site(i, sites[i]);
      if constexpr(!CGAL::parameters::is_default_parameter<CGAL_NP_CLASS, internal_np::site_weight_map_t>::value)
        diagram.set_site_weight(i, internal::site_weight(get_parameter(np, internal_np::site_weight_map), sites[i], i));
    }
    diagram.update();
  }
  result.sites = sites;
  return result;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_VALID_DUAL_SITES_H
