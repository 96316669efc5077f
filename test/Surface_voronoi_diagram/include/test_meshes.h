// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Generated triangle meshes for the tests, the benchmarks and the manual's figures (test
// fixtures, not part of the library). The thin-walled closed shells are the interesting ones:
// their two wall sides are only `thickness` apart in space but far apart along the surface,
// which is exactly where a Euclidean restricted Voronoi diagram leaks through the wall and a
// geodesic one must not. Everything is deterministic, so a test that fails once fails every
// time, and the regression matrix's meshes can be written again (make_test_mesh).
//
// CGAL's own generators are used where they build the very same mesh: Loop subdivision and
// the soup-to-mesh conversion. Its icosahedron and grid are different meshes (see
// make_icosphere() and make_planar_grid()), so those stay ours.

#ifndef SVD_TEST_MESHES_H
#define SVD_TEST_MESHES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace svd_test {
namespace meshes {

/// Parameters shared by every closed thin-walled shell.
///
/// All lengths are relative: the smooth shape the mesh approximates is scaled so
/// that its bounding-box diagonal is `size`, and the wall is
/// `thickness * size` thick, so that one `thickness` means the same thing
/// whatever the shape.
struct Shell_options
{
  /// Wanted number of vertices; the result is usually within a few percent.
  std::size_t target_vertices = 10000;
  /// Wall thickness as a fraction of `size`.
  double thickness = 0.005;
  /// Bounding-box diagonal of the (smooth) shape.
  double size = 1.0;
  /// Edges across each rim (the faces that close the wall at its open ends);
  /// 0 lets the generator pick about `thickness / edge length`, at least 1.
  std::size_t rim_segments = 0;
};

/// A truncated cone wall, open at both ends. Radii and height are proportions
/// of the outer surface, rescaled to `size`.
struct Lampshade_options : Shell_options
{
  double bottom_radius = 1.0;
  double top_radius = 0.6;
  double height = 1.2;
};

/// A cylindrical wall with a bottom. Proportions of the outer surface.
struct Pot_options : Shell_options
{
  double radius = 1.0;
  double height = 1.0;
};

/// A flat plate `width x depth x (thickness * size)`; width and depth are
/// proportions, rescaled so that the plate's bounding-box diagonal is `size`.
struct Slab_options : Shell_options
{
  double width = 1.0;
  double depth = 0.75;
};

/// An open-top box with five solid walls. Proportions of the outer box.
struct Box_options : Shell_options
{
  double width = 1.0;
  double depth = 0.8;
  double height = 0.6;
};

/// A plate folded into a U. `length` (the flat sheets, from the bend axis to
/// their free ends) and `width` (along the bend axis) are proportions; `gap`
/// is the distance between the two inner sheet faces in units of the wall
/// thickness, so the default puts the sheets `2 * thickness * size` apart.
struct U_fold_options : Shell_options
{
  double length = 1.0;
  double width = 0.6;
  double gap = 2.0;
};

/// The shapes `make_shape()` can build.
enum class Shape { sphere, torus, grid, lampshade, vase, pot, u_fold, slab, bowl, box };

namespace internal {

typedef std::array<double, 3> Vec3;
typedef std::array<double, 2> Vec2;

constexpr double pi = 3.14159265358979323846;

inline Vec3 sub3(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vec3 add3(const Vec3& a, const Vec3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
inline Vec3 scale3(const Vec3& a, double s) { return {{a[0] * s, a[1] * s, a[2] * s}}; }
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }
inline Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Vec2 lerp2(const Vec2& a, const Vec2& b, double s)
{
  return {{a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])}};
}
inline double dist2d(const Vec2& a, const Vec2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

inline double corner_angle(const Vec3& p, const Vec3& q, const Vec3& r)
{
  const Vec3 u = sub3(q, p), v = sub3(r, p);
  return std::atan2(norm3(cross3(u, v)), dot3(u, v));
}

inline double triangle_min_angle(const Vec3& p, const Vec3& q, const Vec3& r)
{
  return (std::min)({corner_angle(p, q, r), corner_angle(q, r, p), corner_angle(r, p, q)});
}

// An indexed triangle soup: the shapes are assembled here and only copied into
// the caller's graph once complete, so that orientation can be fixed globally
// and the target vertex count can be met by rebuilding cheaply.
struct Soup
{
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3> > triangles;

  std::size_t add_point(const Vec3& p)
  {
    points.push_back(p);
    return points.size() - 1;
  }

  void add_triangle(std::size_t a, std::size_t b, std::size_t c)
  {
    triangles.push_back({{a, b, c}});
  }

  // Quad a,b,c,d given in boundary order; the diagonal that keeps the smallest
  // angle largest is chosen, which matters on the trapezoids of tori and rims.
  void add_quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d)
  {
    const Vec3 &pa = points[a], &pb = points[b], &pc = points[c], &pd = points[d];
    const double via_ac = (std::min)(triangle_min_angle(pa, pb, pc), triangle_min_angle(pa, pc, pd));
    const double via_bd = (std::min)(triangle_min_angle(pa, pb, pd), triangle_min_angle(pb, pc, pd));
    if(via_ac >= via_bd) {
      add_triangle(a, b, c);
      add_triangle(a, c, d);
    } else {
      add_triangle(a, b, d);
      add_triangle(b, c, d);
    }
  }

  // Same, but orients the quad so that its normal points along `outward`; lets
  // the box-like shapes list faces without caring about corner order.
  void add_quad_facing(std::size_t a, std::size_t b, std::size_t c, std::size_t d, const Vec3& outward)
  {
    const Vec3 n = cross3(sub3(points[c], points[a]), sub3(points[d], points[b]));
    if(dot3(n, outward) < 0)
      add_quad(a, d, c, b);
    else
      add_quad(a, b, c, d);
  }

  double signed_volume() const
  {
    double v = 0;
    for(const auto& t : triangles)
      v += dot3(points[t[0]], cross3(points[t[1]], points[t[2]]));
    return v / 6;
  }

  // Outward orientation is decided once for the whole closed surface instead of
  // per construction step, which would be easy to get wrong shape by shape.
  void orient_outward()
  {
    if(signed_volume() < 0)
      for(auto& t : triangles)
        std::swap(t[1], t[2]);
  }
};

// Merges points that several flat pieces compute independently along their
// common edges; round-off makes them differ in the last bits.
class Welder
{
public:
  Welder(Soup& soup, double tolerance) : soup_(soup), tolerance_(tolerance) {}

  std::size_t vertex(const Vec3& p)
  {
    const Key k = key(p);
    for(long long dx = -1; dx <= 1; ++dx)
      for(long long dy = -1; dy <= 1; ++dy)
        for(long long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(Key{{k[0] + dx, k[1] + dy, k[2] + dz}});
          if(it != cells_.end() && norm3(sub3(soup_.points[it->second], p)) <= tolerance_)
            return it->second;
        }
    const std::size_t i = soup_.add_point(p);
    cells_.emplace(k, i);
    return i;
  }

private:
  typedef std::array<long long, 3> Key;
  struct Key_hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = 1469598103934665603ull;
      for(long long c : k)
        h = (h ^ static_cast<std::uint64_t>(c)) * 1099511628211ull;
      return static_cast<std::size_t>(h);
    }
  };

  Key key(const Vec3& p) const
  {
    return Key{{std::llround(p[0] / tolerance_), std::llround(p[1] / tolerance_),
                std::llround(p[2] / tolerance_)}};
  }

  Soup& soup_;
  double tolerance_;
  std::unordered_map<Key, std::size_t, Key_hash> cells_;
};

// The soup into `out` (cleared first) by CGAL's polygon_soup_to_polygon_mesh(): vertices in
// soup order, then one face per triangle, in order.
template <class MutableFaceGraph>
void write_soup(const Soup& soup, MutableFaceGraph& out)
{
  typedef typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type Vpm;
  typedef typename boost::property_traits<Vpm>::value_type Point;

  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.triangles))
    throw std::logic_error("svd_test::meshes: generated a non-manifold soup (internal error)");
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const Vec3& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  CGAL::clear(out);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.triangles, out);
}

inline void check_positive(double value, const char* what, const char* who)
{
  if(!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(who) + ": " + what + " must be positive and finite (got " +
                                std::to_string(value) + ")");
}

inline void check_shell_options(const Shell_options& o, const char* who)
{
  if(o.target_vertices < 100)
    throw std::invalid_argument(std::string(who) + ": target_vertices must be at least 100 (got " +
                                std::to_string(o.target_vertices) + ")");
  check_positive(o.thickness, "thickness", who);
  check_positive(o.size, "size", who);
}

inline void check_thickness(bool ok, const char* who, const char* limit)
{
  if(!ok)
    throw std::invalid_argument(std::string(who) + ": thickness too large, it must be below " + limit);
}

// Rebuilds with a rescaled edge length until the vertex count is close to the
// target; the count is a step function of the edge length, so a few rounds of
// the area law (count ~ 1/h^2) are enough.
template <class Build>
Soup fit_vertex_count(const Build& build, double h, std::size_t target)
{
  Soup best;
  std::size_t best_error = (std::numeric_limits<std::size_t>::max)();
  for(int round = 0; round < 8; ++round) {
    Soup soup = build(h);
    const std::size_t n = soup.points.size();
    const std::size_t error = n > target ? n - target : target - n;
    if(error < best_error) {
      best_error = error;
      best = std::move(soup);
    }
    if(error * 100 <= target)
      break;
    h *= std::sqrt(double(n) / double(target));
  }
  return best;
}

// Structured grid over the bilinear patch p00,p10,p11,p01, facing `outward`.
inline void add_grid(Welder& welder, Soup& soup, const Vec3& p00, const Vec3& p10, const Vec3& p11,
                     const Vec3& p01, std::size_t na, std::size_t nb, const Vec3& outward)
{
  std::vector<std::size_t> ids((na + 1) * (nb + 1));
  for(std::size_t j = 0; j <= nb; ++j)
    for(std::size_t i = 0; i <= na; ++i) {
      const double u = double(i) / double(na), v = double(j) / double(nb);
      Vec3 p;
      for(int c = 0; c < 3; ++c)
        p[c] = (1 - u) * (1 - v) * p00[c] + u * (1 - v) * p10[c] + u * v * p11[c] + (1 - u) * v * p01[c];
      ids[j * (na + 1) + i] = welder.vertex(p);
    }
  for(std::size_t j = 0; j < nb; ++j)
    for(std::size_t i = 0; i < na; ++i)
      soup.add_quad_facing(ids[j * (na + 1) + i], ids[j * (na + 1) + i + 1], ids[(j + 1) * (na + 1) + i + 1],
                           ids[(j + 1) * (na + 1) + i], outward);
}

// The five or six faces of an axis-aligned box; `sign` -1 makes them face
// inwards, which is what a cavity needs.
inline void add_box_faces(Welder& welder, Soup& soup, const Vec3& lo, const Vec3& hi,
                          const std::array<std::size_t, 3>& n, bool with_top, double sign)
{
  const double x0 = lo[0], y0 = lo[1], z0 = lo[2], x1 = hi[0], y1 = hi[1], z1 = hi[2];
  add_grid(welder, soup, {{x0, y0, z0}}, {{x1, y0, z0}}, {{x1, y1, z0}}, {{x0, y1, z0}}, n[0], n[1],
           {{0, 0, -sign}});
  if(with_top)
    add_grid(welder, soup, {{x0, y0, z1}}, {{x1, y0, z1}}, {{x1, y1, z1}}, {{x0, y1, z1}}, n[0], n[1],
             {{0, 0, sign}});
  add_grid(welder, soup, {{x0, y0, z0}}, {{x1, y0, z0}}, {{x1, y0, z1}}, {{x0, y0, z1}}, n[0], n[2],
           {{0, -sign, 0}});
  add_grid(welder, soup, {{x0, y1, z0}}, {{x1, y1, z0}}, {{x1, y1, z1}}, {{x0, y1, z1}}, n[0], n[2],
           {{0, sign, 0}});
  add_grid(welder, soup, {{x0, y0, z0}}, {{x0, y1, z0}}, {{x0, y1, z1}}, {{x0, y0, z1}}, n[1], n[2],
           {{-sign, 0, 0}});
  add_grid(welder, soup, {{x1, y0, z0}}, {{x1, y1, z0}}, {{x1, y1, z1}}, {{x1, y0, z1}}, n[1], n[2],
           {{sign, 0, 0}});
}

inline std::size_t count_for(double length, double h)
{
  return (std::max<std::size_t>)(1, static_cast<std::size_t>(std::lround(length / h)));
}

inline std::size_t rim_count(const Shell_options& o, double t, double h)
{
  return o.rim_segments > 0 ? o.rim_segments : count_for(t, h);
}

// ---------------------------------------------------------------------------
// Surfaces of revolution around the z axis, described by a profile in the
// (r, z) half-plane made of pieces that meet at corners (corners are kept as
// sample points so that rims stay sharp).

struct Profile_piece
{
  std::vector<Vec2> points;  // dense polyline, points[0] is the previous piece's last point
  std::size_t segments = 0;  // > 0 forces the number of samples (rims)
  double arc_radius = 0;     // > 0: the piece is an arc of this radius...
  double arc_center_z = 0;   // ...centred on the axis here, and samples are put back on it
};

inline Profile_piece line_piece(const Vec2& a, const Vec2& b, std::size_t segments = 0)
{
  Profile_piece piece;
  piece.points = {a, b};
  piece.segments = segments;
  return piece;
}

inline Profile_piece arc_piece(double radius, double from, double to, double z_center = 0)
{
  Profile_piece piece;
  piece.arc_radius = radius;
  piece.arc_center_z = z_center;
  const std::size_t n = 2000;
  for(std::size_t i = 0; i <= n; ++i) {
    const double a = from + (to - from) * double(i) / double(n);
    piece.points.push_back({{radius * std::cos(a), z_center + radius * std::sin(a)}});
  }
  return piece;
}

// Edge lengths along the profile are h*sqrt(3)/2 and along the rings h, and
// every other ring is rotated by half a step: the triangles between two rings
// are then close to equilateral.
inline std::vector<Vec2> sample_profile(const std::vector<Profile_piece>& pieces, bool closed_loop,
                                        double thickness, double h)
{
  const double d = h * std::sqrt(3.0) / 2;
  std::vector<Vec2> samples;
  for(std::size_t p = 0; p < pieces.size(); ++p) {
    const std::vector<Vec2>& pts = pieces[p].points;
    const std::size_t forced = pieces[p].segments;
    std::vector<double> curvature(pts.size(), 0.0);
    for(std::size_t i = 1; i + 1 < pts.size(); ++i) {
      const double ax = pts[i][0] - pts[i - 1][0], az = pts[i][1] - pts[i - 1][1];
      const double bx = pts[i + 1][0] - pts[i][0], bz = pts[i + 1][1] - pts[i][1];
      const double ds = 0.5 * (std::hypot(ax, az) + std::hypot(bx, bz));
      if(ds > 0)
        curvature[i] = std::abs(std::atan2(ax * bz - az * bx, ax * bx + az * bz)) / ds;
    }
    // Samples are spread evenly in a cost that is arc length over the longest
    // segment allowed there: d where the profile is straight, less where it
    // bends, so that coarse meshes still bend smoothly and the chord error
    // stays below a third of the wall thickness; otherwise the two sides of a
    // thin wall could cross each other.
    std::vector<double> cost(pts.size(), 0.0);
    for(std::size_t i = 1; i < pts.size(); ++i) {
      const double length = dist2d(pts[i - 1], pts[i]);
      const double kappa = (std::max)(curvature[i - 1], curvature[i]);
      double limit = d;
      if(kappa > 0) {
        limit = (std::min)(limit, (pi / 6) / kappa);
        const double c = 1 - thickness * kappa / 3;
        if(c > -1)
          limit = (std::min)(limit, 2 * std::acos(c) / kappa);
      }
      cost[i] = cost[i - 1] + (forced > 0 ? length : length / limit);
    }
    const double total = cost.back();
    const std::size_t m =
        forced > 0 ? forced : (std::max<std::size_t>)(1, static_cast<std::size_t>(std::lround(total)));
    for(std::size_t j = 0; j < m; ++j) {
      const double c = total * double(j) / double(m);
      std::size_t i = static_cast<std::size_t>(std::upper_bound(cost.begin(), cost.end(), c) - cost.begin());
      i = (std::min)((std::max)(i, std::size_t(1)), pts.size() - 1);
      const double span = cost[i] - cost[i - 1];
      Vec2 q = lerp2(pts[i - 1], pts[i], span > 0 ? (c - cost[i - 1]) / span : 0.0);
      if(pieces[p].arc_radius > 0 && j > 0) {
        // The dense polyline's chords lie inside the circle; a sphere's
        // vertices should be on it exactly.
        const double dz = q[1] - pieces[p].arc_center_z, len = std::hypot(q[0], dz);
        q = {{q[0] * pieces[p].arc_radius / len, pieces[p].arc_center_z + dz * pieces[p].arc_radius / len}};
      }
      samples.push_back(q);
    }
  }
  if(!closed_loop)
    samples.push_back(pieces.back().points.back());
  return samples;
}

inline std::size_t ring_size(const std::vector<Vec2>& samples, std::size_t k, bool closed_loop,
                             double thickness, double h)
{
  const std::size_t K = samples.size();
  if(!closed_loop && (k == 0 || k + 1 == K))
    return 1;
  const double r = samples[k][0];
  std::size_t n = (std::max<std::size_t>)(3, static_cast<std::size_t>(std::lround(2 * pi * r / h)));
  // Polygon chords cut into the solid by r (1 - cos(pi / n)) in the radial
  // direction (kept below a third of the thickness, as along the profile),
  // which only brings the other wall side closer where the profile
  // runs along z: weight by the radial part of the profile normal.
  double radial = 0;
  for(std::size_t other : {(k + K - 1) % K, (k + 1) % K}) {
    const double len = dist2d(samples[k], samples[other]);
    if(len > 0)
      radial = (std::max)(radial, std::abs(samples[other][1] - samples[k][1]) / len);
  }
  const double c = 1 - thickness / (3 * r * radial);
  if(radial > 0 && c > -1)
    n = (std::max)(n, static_cast<std::size_t>(std::ceil(pi / std::acos(c))));
  return n;
}

// Joins two consecutive rings with a strip of triangles, advancing on the ring
// whose next vertex gives the shorter new edge (this copes with rings of
// different sizes and with the half-step stagger).
inline void stitch_rings(Soup& soup, std::size_t a0, std::size_t na, double phase_a, std::size_t b0,
                         std::size_t nb, double phase_b)
{
  if(na == 1) {
    for(std::size_t k = 0; k < nb; ++k)
      soup.add_triangle(a0, b0 + (k + 1) % nb, b0 + k);
    return;
  }
  if(nb == 1) {
    for(std::size_t i = 0; i < na; ++i)
      soup.add_triangle(a0 + i, a0 + (i + 1) % na, b0);
    return;
  }
  const double step_b = 2 * pi / double(nb);
  const long long before = static_cast<long long>(std::floor((phase_a - phase_b) / step_b));
  const std::size_t k0 = static_cast<std::size_t>(((before % (long long)nb) + (long long)nb) % (long long)nb);
  auto A = [&](std::size_t i) { return a0 + i % na; };
  auto B = [&](std::size_t k) { return b0 + (k0 + k) % nb; };
  auto length = [&](std::size_t u, std::size_t v) { return norm3(sub3(soup.points[u], soup.points[v])); };
  std::size_t i = 0, k = 0;
  while(i < na || k < nb) {
    bool advance_a;
    if(i == na)
      advance_a = false;
    else if(k == nb)
      advance_a = true;
    else
      advance_a = length(A(i + 1), B(k)) <= length(A(i), B(k + 1));
    if(advance_a) {
      soup.add_triangle(A(i), A(i + 1), B(k));
      ++i;
    } else {
      soup.add_triangle(A(i), B(k + 1), B(k));
      ++k;
    }
  }
}

inline Soup revolve(const std::vector<Profile_piece>& pieces, bool closed_loop, double thickness, double h)
{
  const std::vector<Vec2> samples = sample_profile(pieces, closed_loop, thickness, h);
  const std::size_t K = samples.size();
  std::vector<std::size_t> start(K), size(K);
  std::vector<double> phase(K);
  Soup soup;
  for(std::size_t k = 0; k < K; ++k)
    size[k] = ring_size(samples, k, closed_loop, thickness, h);
  // Rings much closer than an edge length lie across a rim: give them one
  // size so that the half-step stagger holds all around. With sizes n and
  // n + 1 the rings would drift in and out of phase and the rim would get
  // right triangles, twice as flat as the staggered isosceles ones.
  for(bool changed = true; changed;) {
    changed = false;
    for(std::size_t k = 0; k < K; ++k) {
      const std::size_t next = (k + 1) % K;
      if((next == 0 && !closed_loop) || size[k] == 1 || size[next] == 1 || size[k] == size[next] ||
         dist2d(samples[k], samples[next]) >= 0.25 * h)
        continue;
      size[k] = size[next] = (std::max)(size[k], size[next]);
      changed = true;
    }
  }
  for(std::size_t k = 0; k < K; ++k) {
    start[k] = soup.points.size();
    phase[k] = (k % 2 == 1) ? pi / double(size[k]) : 0.0;
    const double r = samples[k][0], z = samples[k][1];
    if(size[k] == 1) {
      soup.add_point({{0.0, 0.0, z}});
      continue;
    }
    for(std::size_t j = 0; j < size[k]; ++j) {
      const double a = phase[k] + 2 * pi * double(j) / double(size[k]);
      soup.add_point({{r * std::cos(a), r * std::sin(a), z}});
    }
  }
  for(std::size_t k = 0; k + 1 < K; ++k)
    stitch_rings(soup, start[k], size[k], phase[k], start[k + 1], size[k + 1], phase[k + 1]);
  if(closed_loop)
    stitch_rings(soup, start[K - 1], size[K - 1], phase[K - 1], start[0], size[0], phase[0]);
  soup.orient_outward();
  return soup;
}

inline Soup revolve_to_target(const std::vector<Profile_piece>& pieces, bool closed_loop, double thickness,
                              std::size_t target)
{
  double area = 0;  // Pappus, on the dense profile
  for(const Profile_piece& piece : pieces)
    for(std::size_t i = 1; i < piece.points.size(); ++i)
      area += 2 * pi * 0.5 * (piece.points[i - 1][0] + piece.points[i][0]) *
              dist2d(piece.points[i - 1], piece.points[i]);
  // One vertex per sqrt(3)/2 h^2 of area in an equilateral mesh.
  const double h = std::sqrt(2 * area / (std::sqrt(3.0) * double(target)));
  return fit_vertex_count([&](double hh) { return revolve(pieces, closed_loop, thickness, hh); }, h, target);
}

// The vase's outer radius along its height (unit height): smooth cosine blends
// between a foot, a belly, a neck and a slightly flared lip, with a vertical
// tangent at each of them so the lip ends in a horizontal rim.
inline void vase_profile(double u, double& r, double& dr)
{
  static const double us[] = {0.0, 0.38, 0.80, 1.0};
  static const double rs[] = {0.26, 0.42, 0.17, 0.25};
  std::size_t s = 0;
  while(s < 2 && u > us[s + 1])
    ++s;
  const double span = us[s + 1] - us[s];
  const double w = (std::min)(1.0, (std::max)(0.0, (u - us[s]) / span));
  r = rs[s] + (rs[s + 1] - rs[s]) * (1 - std::cos(pi * w)) / 2;
  dr = (rs[s + 1] - rs[s]) * pi * std::sin(pi * w) / (2 * span);
}

// Not CGAL::make_icosahedron(): its 12 vertices and 20 faces come in another order, so every subdivided sphere would be another mesh.
inline Soup icosphere(int levels, double radius)
{
  const double phi = (1 + std::sqrt(5.0)) / 2;
  Soup soup;
  for(double a : {-1.0, 1.0})
    for(double b : {-phi, phi}) {
      soup.add_point({{0, a, b}});
      soup.add_point({{a, b, 0}});
      soup.add_point({{b, 0, a}});
    }
  // The icosahedron's faces are exactly its triples of vertices at mutual
  // distance 2; deriving them avoids a hand-typed table.
  for(std::size_t i = 0; i < 12; ++i)
    for(std::size_t j = i + 1; j < 12; ++j)
      for(std::size_t k = j + 1; k < 12; ++k) {
        const Vec3 &a = soup.points[i], &b = soup.points[j], &c = soup.points[k];
        auto is_edge = [](const Vec3& p, const Vec3& q) { return std::abs(dot3(sub3(p, q), sub3(p, q)) - 4) < 1e-9; };
        if(!is_edge(a, b) || !is_edge(b, c) || !is_edge(a, c))
          continue;
        if(dot3(cross3(sub3(b, a), sub3(c, a)), add3(add3(a, b), c)) > 0)
          soup.add_triangle(i, j, k);
        else
          soup.add_triangle(i, k, j);
      }
  auto project = [radius](const Vec3& p) { return scale3(p, radius / norm3(p)); };
  for(Vec3& p : soup.points)
    p = project(p);
  // Midpoints are projected at every level (not once at the end), which keeps
  // the triangle sizes far more even over the sphere.
  for(int level = 0; level < levels; ++level) {
    std::unordered_map<std::uint64_t, std::size_t> midpoints;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const std::uint64_t key = (std::uint64_t((std::min)(a, b)) << 32) | std::uint64_t((std::max)(a, b));
      auto it = midpoints.find(key);
      if(it != midpoints.end())
        return it->second;
      const std::size_t m = soup.add_point(project(add3(soup.points[a], soup.points[b])));
      midpoints.emplace(key, m);
      return m;
    };
    std::vector<std::array<std::size_t, 3> > coarse;
    coarse.swap(soup.triangles);
    for(const auto& t : coarse) {
      const std::size_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      soup.add_triangle(t[0], ab, ca);
      soup.add_triangle(ab, t[1], bc);
      soup.add_triangle(ca, bc, t[2]);
      soup.add_triangle(ab, bc, ca);
    }
  }
  return soup;
}

} // namespace internal

/// Writes into `out` (cleared first) an icosphere: the regular icosahedron,
/// refined `subdivisions` times by splitting each triangle in four, with new
/// vertices projected onto the sphere at every level. It has
/// `10 * 4^subdivisions + 2` vertices, all at distance `radius` from the origin,
/// and nearly equal triangles, so the Laplace-Beltrami eigenvalues are close to
/// `l (l + 1) / radius^2`.
/// \throws std::invalid_argument unless `0 <= subdivisions <= 10` and `radius > 0`.
template <class MutableFaceGraph>
void make_icosphere(MutableFaceGraph& out, int subdivisions, double radius = 1.0)
{
  if(subdivisions < 0 || subdivisions > 10)
    throw std::invalid_argument("make_icosphere: subdivisions must be in [0, 10] (got " +
                                std::to_string(subdivisions) + ")");
  internal::check_positive(radius, "radius", "make_icosphere");
  internal::write_soup(internal::icosphere(subdivisions, radius), out);
}

/// Writes into `out` (cleared first) a torus around the z axis: `nu` segments
/// along the big circle of radius `major_radius`, `nv` around the tube of
/// radius `minor_radius`; each grid quad is split along the diagonal that keeps
/// the better angles.
/// \throws std::invalid_argument unless `0 < minor_radius < major_radius`, `nu >= 3` and `nv >= 3`.
template <class MutableFaceGraph>
void make_torus(MutableFaceGraph& out, double major_radius, double minor_radius, std::size_t nu, std::size_t nv)
{
  internal::check_positive(minor_radius, "minor_radius", "make_torus");
  internal::check_positive(major_radius, "major_radius", "make_torus");
  if(!(minor_radius < major_radius))
    throw std::invalid_argument("make_torus: minor_radius must be smaller than major_radius");
  if(nu < 3 || nv < 3)
    throw std::invalid_argument("make_torus: nu and nv must be at least 3");
  internal::Soup soup;
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * internal::pi * double(i) / double(nu), v = 2 * internal::pi * double(j) / double(nv);
      const double rho = major_radius + minor_radius * std::cos(v);
      soup.add_point({{rho * std::cos(u), rho * std::sin(u), minor_radius * std::sin(v)}});
    }
  auto id = [nu, nv](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j)
      soup.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  soup.orient_outward();
  internal::write_soup(soup, out);
}

/// Writes into `out` (cleared first) the rectangle `[0, width] x [0, height]`
/// of the plane z = 0, facing +z, as a grid of `nx x ny` vertices whose cells are
/// split along alternating diagonals (so the mesh has no preferred direction).
/// With `jitter > 0` every interior vertex moves by up to `jitter` times the
/// grid spacing in x and in y, drawn from `std::mt19937(seed)`; below 1/4 no
/// triangle can flip, and the boundary stays exact so the area is
/// `width * height`.
/// \throws std::invalid_argument unless `nx, ny >= 2`, `width, height > 0` and `0 <= jitter < 0.25`.
// Not CGAL::make_grid(): it splits every cell along the same diagonal, faces column by column (ours alternate, row by row).
template <class MutableFaceGraph>
void make_planar_grid(MutableFaceGraph& out, std::size_t nx, std::size_t ny, double width = 1.0,
                      double height = 1.0, double jitter = 0.0, unsigned int seed = 0)
{
  if(nx < 2 || ny < 2)
    throw std::invalid_argument("make_planar_grid: nx and ny (vertices per row and column) must be at least 2");
  internal::check_positive(width, "width", "make_planar_grid");
  internal::check_positive(height, "height", "make_planar_grid");
  if(!(jitter >= 0 && jitter < 0.25))
    throw std::invalid_argument("make_planar_grid: jitter must be in [0, 0.25) (got " + std::to_string(jitter) +
                                ")");
  const double dx = width / double(nx - 1), dy = height / double(ny - 1);
  // The engine's output sequence is fixed by the standard, unlike the
  // standard distributions, so the jitter is the same on every platform.
  std::mt19937 engine(seed);
  auto uniform = [&engine]() { return 2 * (double(engine()) / 4294967296.0) - 1; };
  internal::Soup soup;
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      double x = (i + 1 == nx) ? width : dx * double(i);
      double y = (j + 1 == ny) ? height : dy * double(j);
      if(jitter > 0 && i > 0 && j > 0 && i + 1 < nx && j + 1 < ny) {
        x += jitter * dx * uniform();
        y += jitter * dy * uniform();
      }
      soup.add_point({{x, y, 0.0}});
    }
  for(std::size_t j = 0; j + 1 < ny; ++j)
    for(std::size_t i = 0; i + 1 < nx; ++i) {
      const std::size_t a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      if((i + j) % 2 == 0) {
        soup.add_triangle(a, b, c);
        soup.add_triangle(a, c, d);
      } else {
        soup.add_triangle(a, b, d);
        soup.add_triangle(b, c, d);
      }
    }
  internal::write_soup(soup, out);
}

/// Writes into `out` (cleared first) a lampshade: a truncated cone wall around
/// the z axis standing on z = 0, open at both ends, whose outer and inner
/// surfaces are `thickness * size` apart and are joined by flat rims in the
/// planes z = 0 and z = height. Being a thick tube it has the topology of a
/// torus (Euler characteristic 0).
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a wall thicker than a quarter of the top radius.
template <class MutableFaceGraph>
void make_thin_lampshade(MutableFaceGraph& out, const Lampshade_options& options = Lampshade_options())
{
  const char* who = "make_thin_lampshade";
  internal::check_shell_options(options, who);
  internal::check_positive(options.bottom_radius, "bottom_radius", who);
  internal::check_positive(options.top_radius, "top_radius", who);
  internal::check_positive(options.height, "height", who);
  const double big = (std::max)(options.bottom_radius, options.top_radius);
  const double s = options.size / std::sqrt(8 * big * big + options.height * options.height);
  const double r0 = s * options.bottom_radius, r1 = s * options.top_radius, H = s * options.height;
  const double t = options.thickness * options.size;
  internal::check_thickness(t < 0.25 * (std::min)({r0, r1, H}), who, "a quarter of the smaller radius");

  // The inner wall is the outer line moved by t along its inward normal and
  // cut by the rim planes, so the wall is exactly t thick.
  const double L = std::hypot(r1 - r0, H);
  const double tr = (r1 - r0) / L, tz = H / L;  // unit tangent, bottom to top
  const double nr = -tz, nz = tr;                // inward normal
  auto inner_at = [&](double z) {
    const double lambda = (z - t * nz) / tz;     // along the tangent from (r0 + t nr, t nz)
    return internal::Vec2{{r0 + t * nr + lambda * tr, z}};
  };
  const internal::Vec2 outer_bottom{{r0, 0.0}}, outer_top{{r1, H}};
  const internal::Vec2 inner_top = inner_at(H), inner_bottom = inner_at(0.0);
  const std::size_t forced = options.rim_segments;
  std::vector<internal::Profile_piece> pieces = {
      internal::line_piece(outer_bottom, outer_top), internal::line_piece(outer_top, inner_top, forced),
      internal::line_piece(inner_top, inner_bottom), internal::line_piece(inner_bottom, outer_bottom, forced)};
  internal::write_soup(internal::revolve_to_target(pieces, true, t, options.target_vertices), out);
}

/// Writes into `out` (cleared first) a vase: a surface of revolution around the
/// z axis with a curved profile (foot, belly, narrow neck, flared lip), a flat
/// bottom and a horizontal rim at the lip. The inner surface is the outer one
/// offset by `thickness * size` along its normal, and the bottom is as thick.
/// Topologically a sphere.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a wall thicker than a quarter of the neck radius.
template <class MutableFaceGraph>
void make_thin_vase(MutableFaceGraph& out, const Shell_options& options = Shell_options())
{
  const char* who = "make_thin_vase";
  internal::check_shell_options(options, who);
  const double max_radius = 0.42, neck_radius = 0.17;
  const double s = options.size / std::sqrt(8 * max_radius * max_radius + 1);
  const double H = s, t = options.thickness * options.size;
  internal::check_thickness(t < 0.25 * s * neck_radius, who, "a quarter of the neck radius");

  const std::size_t n = 4000;
  internal::Profile_piece outer, inner;
  for(std::size_t i = 0; i <= n; ++i) {
    const double u = double(i) / double(n);
    double r, dr;
    internal::vase_profile(u, r, dr);
    // Tangent (s dr, H) per unit u; the inward normal turns it towards the axis.
    const double tr = s * dr, tz = H, len = std::hypot(tr, tz);
    const internal::Vec2 p{{s * r, H * u}};
    outer.points.push_back(p);
    inner.points.push_back({{p[0] - t * tz / len, p[1] + t * tr / len}});
  }
  // The offset curve starts below the inner bottom (z = t); cut it there.
  std::vector<internal::Vec2> clipped;
  for(std::size_t i = 0; i < inner.points.size(); ++i) {
    const internal::Vec2& q = inner.points[i];
    if(q[1] < t)
      continue;
    if(clipped.empty() && i > 0) {
      const internal::Vec2& prev = inner.points[i - 1];
      clipped.push_back(internal::lerp2(prev, q, (t - prev[1]) / (q[1] - prev[1])));
      clipped.back()[1] = t;
    }
    clipped.push_back(q);
  }
  clipped.back()[1] = H;  // vertical tangent at the lip: the offset ends on the rim plane
  std::reverse(clipped.begin(), clipped.end());
  inner.points = clipped;

  std::vector<internal::Profile_piece> pieces;
  pieces.push_back(internal::line_piece({{0.0, 0.0}}, outer.points.front()));
  pieces.push_back(outer);
  pieces.push_back(internal::line_piece(outer.points.back(), inner.points.front(), options.rim_segments));
  pieces.push_back(inner);
  pieces.push_back(internal::line_piece(inner.points.back(), {{0.0, t}}));
  internal::write_soup(internal::revolve_to_target(pieces, false, t, options.target_vertices), out);
}

/// Writes into `out` (cleared first) a pot: a cylindrical wall around the z axis
/// on a flat bottom at z = 0, both `thickness * size` thick, with a flat rim at
/// the top. Topologically a sphere.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a wall thicker than a quarter of the radius or height.
template <class MutableFaceGraph>
void make_thin_pot(MutableFaceGraph& out, const Pot_options& options = Pot_options())
{
  const char* who = "make_thin_pot";
  internal::check_shell_options(options, who);
  internal::check_positive(options.radius, "radius", who);
  internal::check_positive(options.height, "height", who);
  const double s = options.size / std::sqrt(8 * options.radius * options.radius + options.height * options.height);
  const double R = s * options.radius, H = s * options.height, t = options.thickness * options.size;
  internal::check_thickness(t < 0.25 * (std::min)(R, H), who, "a quarter of the radius and of the height");
  std::vector<internal::Profile_piece> pieces = {
      internal::line_piece({{0.0, 0.0}}, {{R, 0.0}}), internal::line_piece({{R, 0.0}}, {{R, H}}),
      internal::line_piece({{R, H}}, {{R - t, H}}, options.rim_segments),
      internal::line_piece({{R - t, H}}, {{R - t, t}}), internal::line_piece({{R - t, t}}, {{0.0, t}})};
  internal::write_soup(internal::revolve_to_target(pieces, false, t, options.target_vertices), out);
}

/// Writes into `out` (cleared first) a hemispherical bowl: the lower halves of
/// two concentric spheres, `thickness * size` apart, joined by a flat rim in the
/// plane z = 0. Topologically a sphere.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a wall thicker than a quarter of the radius.
template <class MutableFaceGraph>
void make_thin_bowl(MutableFaceGraph& out, const Shell_options& options = Shell_options())
{
  const char* who = "make_thin_bowl";
  internal::check_shell_options(options, who);
  const double R = options.size / 3, t = options.thickness * options.size;
  internal::check_thickness(t < 0.25 * R, who, "a quarter of the radius");
  internal::Profile_piece outer = internal::arc_piece(R, -internal::pi / 2, 0.0);
  internal::Profile_piece inner = internal::arc_piece(R - t, 0.0, -internal::pi / 2);
  // Pin the ends on the axis and on the rim exactly (cos(pi / 2) is not 0).
  outer.points.front() = {{0.0, -R}};
  outer.points.back() = {{R, 0.0}};
  inner.points.front() = {{R - t, 0.0}};
  inner.points.back() = {{0.0, -(R - t)}};
  std::vector<internal::Profile_piece> pieces = {
      outer, internal::line_piece({{R, 0.0}}, {{R - t, 0.0}}, options.rim_segments), inner};
  internal::write_soup(internal::revolve_to_target(pieces, false, t, options.target_vertices), out);
}

/// Writes into `out` (cleared first) a thin flat plate: the closed box
/// `[-a/2, a/2] x [-b/2, b/2] x [-t/2, t/2]` with `t = thickness * size` and
/// `a : b = width : depth`, scaled so that the box's diagonal is `size`.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a thickness above half the smaller side.
template <class MutableFaceGraph>
void make_thin_slab(MutableFaceGraph& out, const Slab_options& options = Slab_options())
{
  const char* who = "make_thin_slab";
  internal::check_shell_options(options, who);
  internal::check_positive(options.width, "width", who);
  internal::check_positive(options.depth, "depth", who);
  const double t = options.thickness * options.size;
  internal::check_thickness(options.thickness < 0.5, who, "half the size");
  const double s = std::sqrt(options.size * options.size - t * t) / std::hypot(options.width, options.depth);
  const double a = s * options.width, b = s * options.depth;
  internal::check_thickness(t < 0.5 * (std::min)(a, b), who, "half the smaller side");
  auto build = [&](double h) {
    internal::Soup soup;
    internal::Welder welder(soup, 1e-9 * options.size);
    internal::add_box_faces(welder, soup, {{-a / 2, -b / 2, -t / 2}}, {{a / 2, b / 2, t / 2}},
                            {{internal::count_for(a, h), internal::count_for(b, h),
                              internal::rim_count(options, t, h)}},
                            true, 1.0);
    soup.orient_outward();
    return soup;
  };
  internal::write_soup(internal::fit_vertex_count(build, std::sqrt(2 * a * b / double(options.target_vertices)),
                                                  options.target_vertices),
                       out);
}

/// Writes into `out` (cleared first) an open-top box whose bottom and four
/// sides are solid plates `thickness * size` thick: the outer box
/// `[-W/2, W/2] x [-D/2, D/2] x [0, H]` minus the cavity
/// `[-W/2 + t, W/2 - t] x [-D/2 + t, D/2 - t] x [t, H]`, the walls closed by a
/// flat rim at z = H. `W : D : H` is `width : depth : height`, scaled to a
/// diagonal of `size`. Topologically a sphere.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or walls thicker than a quarter of the smallest side.
template <class MutableFaceGraph>
void make_thin_walled_box(MutableFaceGraph& out, const Box_options& options = Box_options())
{
  const char* who = "make_thin_walled_box";
  internal::check_shell_options(options, who);
  internal::check_positive(options.width, "width", who);
  internal::check_positive(options.depth, "depth", who);
  internal::check_positive(options.height, "height", who);
  const double s = options.size / std::sqrt(options.width * options.width + options.depth * options.depth +
                                            options.height * options.height);
  const double W = s * options.width, D = s * options.depth, H = s * options.height;
  const double t = options.thickness * options.size;
  internal::check_thickness(t < 0.25 * (std::min)({W, D, H}), who, "a quarter of the smallest side");
  const double x0 = -W / 2, x1 = W / 2, y0 = -D / 2, y1 = D / 2;
  auto build = [&](double h) {
    internal::Soup soup;
    internal::Welder welder(soup, 1e-9 * options.size);
    // Inner walls reuse the outer counts: the rim between them is then a
    // plain strip of quads.
    const std::array<std::size_t, 3> n = {
        {internal::count_for(W, h), internal::count_for(D, h), internal::count_for(H, h)}};
    const std::size_t rows = internal::rim_count(options, t, h);
    internal::add_box_faces(welder, soup, {{x0, y0, 0.0}}, {{x1, y1, H}}, n, false, 1.0);
    internal::add_box_faces(welder, soup, {{x0 + t, y0 + t, t}}, {{x1 - t, y1 - t, H}}, n, false, -1.0);
    const internal::Vec3 up{{0.0, 0.0, 1.0}};
    const internal::Vec3 o00{{x0, y0, H}}, o10{{x1, y0, H}}, o11{{x1, y1, H}}, o01{{x0, y1, H}};
    const internal::Vec3 i00{{x0 + t, y0 + t, H}}, i10{{x1 - t, y0 + t, H}}, i11{{x1 - t, y1 - t, H}},
        i01{{x0 + t, y1 - t, H}};
    internal::add_grid(welder, soup, o00, o10, i10, i00, n[0], rows, up);
    internal::add_grid(welder, soup, o01, o11, i11, i01, n[0], rows, up);
    internal::add_grid(welder, soup, o00, o01, i01, i00, n[1], rows, up);
    internal::add_grid(welder, soup, o10, o11, i11, i10, n[1], rows, up);
    soup.orient_outward();
    return soup;
  };
  const double area = 2 * (W * D + 2 * (W + D) * H);
  internal::write_soup(internal::fit_vertex_count(build, std::sqrt(area / double(options.target_vertices)),
                                                  options.target_vertices),
                       out);
}

/// Writes into `out` (cleared first) a plate `thickness * size` thick folded
/// into a U around the y axis: two flat sheets over `0 <= x <= L`, their inner
/// faces in the planes `z = +-g/2` with `g = gap * thickness * size`, joined
/// for `x <= 0` by a half-cylindrical bend (inner radius g/2, outer radius
/// g/2 + t), the plate spanning `0 <= y <= width`. The free ends at x = L and
/// the two sides y = 0 and y = width are flat rims. Two facing points of the
/// inner faces at distance x from the bend are g apart in space but
/// `2 x + pi g / 2` apart along the surface. `L : width` is `length : width`,
/// scaled so that the bounding-box diagonal is `size`. Topologically a sphere.
/// \throws std::invalid_argument on a non-positive parameter, fewer than 100
/// target vertices, or a fold thicker than a quarter of the sheet width.
template <class MutableFaceGraph>
void make_u_fold(MutableFaceGraph& out, const U_fold_options& options = U_fold_options())
{
  const char* who = "make_u_fold";
  internal::check_shell_options(options, who);
  internal::check_positive(options.length, "length", who);
  internal::check_positive(options.width, "width", who);
  internal::check_positive(options.gap, "gap", who);
  const double t = options.thickness * options.size, g = options.gap * t;
  const double ri = g / 2, ro = g / 2 + t;
  // Solve (s length + ro)^2 + (s width)^2 + (2 ro)^2 = size^2 for the scale s.
  const double qa = options.length * options.length + options.width * options.width;
  const double qb = 2 * options.length * ro, qc = 5 * ro * ro - options.size * options.size;
  if(!(qc < 0))
    throw std::invalid_argument(std::string(who) + ": thickness and gap too large for the size");
  const double s = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  const double L = s * options.length, Wd = s * options.width;
  internal::check_thickness(2 * ro < 0.25 * (std::min)(L, Wd), who,
                            "an eighth of the sheet length and width (with the gap)");

  auto build = [&](double h) {
    // Cross-section in the (x, z) plane: the outer chain and the inner chain
    // have the same number of points, so the two side rims are ladders.
    const std::size_t n_sheet = internal::count_for(L, h);
    const std::size_t n_bend = (std::max<std::size_t>)(4, internal::count_for(internal::pi * ro, h));
    const std::size_t rows = internal::rim_count(options, t, h);
    auto chain = [&](double radius) {
      std::vector<internal::Vec2> c;
      for(std::size_t i = 0; i < n_sheet; ++i)
        c.push_back({{L * (1 - double(i) / double(n_sheet)), -radius}});
      for(std::size_t i = 0; i < n_bend; ++i) {
        const double a = -internal::pi / 2 - internal::pi * double(i) / double(n_bend);
        c.push_back({{i == 0 ? 0.0 : radius * std::cos(a), i == 0 ? -radius : radius * std::sin(a)}});
      }
      for(std::size_t i = 0; i <= n_sheet; ++i)
        c.push_back({{L * double(i) / double(n_sheet), radius}});
      return c;
    };
    const std::vector<internal::Vec2> outer = chain(ro), inner = chain(ri);
    const std::size_t K = outer.size();
    auto across = [&](std::size_t k, std::size_t r) {  // r-th point from outer[k] to inner[k]
      return internal::lerp2(outer[k], inner[k], double(r) / double(rows));
    };
    // Closed loop around the cross-section, counter-clockwise in (x, z).
    std::vector<internal::Vec2> loop(outer);
    for(std::size_t r = 1; r < rows; ++r)
      loop.push_back(across(K - 1, r));
    for(std::size_t k = K; k-- > 0;)
      loop.push_back(inner[k]);
    for(std::size_t r = rows - 1; r >= 1; --r)
      loop.push_back(across(0, r));
    double area2 = 0;
    for(std::size_t k = 0; k < loop.size(); ++k) {
      const internal::Vec2 &p = loop[k], &q = loop[(k + 1) % loop.size()];
      area2 += p[0] * q[1] - q[0] * p[1];
    }
    const double orientation = area2 > 0 ? 1.0 : -1.0;

    internal::Soup soup;
    internal::Welder welder(soup, 1e-9 * options.size);
    const std::size_t ny = internal::count_for(Wd, h);
    auto at = [&](const internal::Vec2& p, std::size_t j) {
      return welder.vertex({{p[0], Wd * double(j) / double(ny), p[1]}});
    };
    const std::size_t M = loop.size();
    std::vector<std::size_t> ids(M * (ny + 1));
    for(std::size_t j = 0; j <= ny; ++j)
      for(std::size_t k = 0; k < M; ++k)
        ids[j * M + k] = at(loop[k], j);
    for(std::size_t k = 0; k < M; ++k) {
      const internal::Vec2 &p = loop[k], &q = loop[(k + 1) % M];
      const internal::Vec3 outward{{orientation * (q[1] - p[1]), 0.0, -orientation * (q[0] - p[0])}};
      for(std::size_t j = 0; j < ny; ++j)
        soup.add_quad_facing(ids[j * M + k], ids[j * M + (k + 1) % M], ids[(j + 1) * M + (k + 1) % M],
                             ids[(j + 1) * M + k], outward);
    }
    for(std::size_t side = 0; side < 2; ++side) {
      const std::size_t j = side == 0 ? 0 : ny;
      const internal::Vec3 outward{{0.0, side == 0 ? -1.0 : 1.0, 0.0}};
      for(std::size_t k = 0; k + 1 < K; ++k)
        for(std::size_t r = 0; r < rows; ++r)
          soup.add_quad_facing(at(across(k, r), j), at(across(k + 1, r), j), at(across(k + 1, r + 1), j),
                               at(across(k, r + 1), j), outward);
    }
    soup.orient_outward();
    return soup;
  };
  const double area = 4 * L * Wd;
  internal::write_soup(internal::fit_vertex_count(build, std::sqrt(area / double(options.target_vertices)),
                                                  options.target_vertices),
                       out);
}

/// Every value of `Shape`, in declaration order.
inline const std::vector<Shape>& all_shapes()
{
  static const std::vector<Shape> shapes = {Shape::sphere,    Shape::torus, Shape::grid,   Shape::lampshade,
                                            Shape::vase,      Shape::pot,   Shape::u_fold, Shape::slab,
                                            Shape::bowl,      Shape::box};
  return shapes;
}

/// The name of `shape` as accepted by `shape_from_name()`.
inline std::string shape_name(Shape shape)
{
  switch(shape) {
  case Shape::sphere: return "sphere";
  case Shape::torus: return "torus";
  case Shape::grid: return "grid";
  case Shape::lampshade: return "lampshade";
  case Shape::vase: return "vase";
  case Shape::pot: return "pot";
  case Shape::u_fold: return "u_fold";
  case Shape::slab: return "slab";
  case Shape::bowl: return "bowl";
  case Shape::box: return "box";
  }
  throw std::invalid_argument("shape_name: not a Shape value");
}

/// The shape called `name` (one of `sphere, torus, grid, lampshade, vase, pot,
/// u_fold, slab, bowl, box`).
/// \throws std::invalid_argument for any other name, listing the valid ones.
inline Shape shape_from_name(const std::string& name)
{
  std::string known;
  for(Shape shape : all_shapes()) {
    if(shape_name(shape) == name)
      return shape;
    known += (known.empty() ? "" : ", ") + shape_name(shape);
  }
  throw std::invalid_argument("unknown shape '" + name + "' (expected one of: " + known + ")");
}

/// Writes `shape` into `out` (cleared first) with about
/// `options.target_vertices` vertices and a bounding-box diagonal of about
/// `options.size`, so that programs can take the shape by name. The thin
/// shells use all the options with their default proportions; the others use
/// only the vertex count and the size: `sphere` is the icosphere whose
/// `10 * 4^k + 2` vertices are closest to the target, `torus` has radii 1 : 0.4
/// and nearly square cells, `grid` is a square `make_planar_grid()` without jitter.
/// \throws std::invalid_argument as the underlying generator does.
template <class MutableFaceGraph>
void make_shape(Shape shape, MutableFaceGraph& out, const Shell_options& options = Shell_options())
{
  const std::size_t target = options.target_vertices;
  switch(shape) {
  case Shape::sphere: {
    internal::check_positive(options.size, "size", "make_shape");
    int best = 0;
    for(int k = 1; k <= 10; ++k)
      if(std::abs(std::log((10.0 * std::pow(4.0, k) + 2) / double(target))) <
         std::abs(std::log((10.0 * std::pow(4.0, best) + 2) / double(target))))
        best = k;
    make_icosphere(out, best, options.size / (2 * std::sqrt(3.0)));
    return;
  }
  case Shape::torus: {
    internal::check_positive(options.size, "size", "make_shape");
    const double R = options.size / std::sqrt(8 * 1.4 * 1.4 + 4 * 0.4 * 0.4), r = 0.4 * R;
    // Square cells along the tube's middle circle: nu / nv = R / r.
    const double nv = std::sqrt(double(target) * r / R);
    make_torus(out, R, r, (std::max<std::size_t>)(3, std::lround(double(target) / nv)),
               (std::max<std::size_t>)(3, std::lround(nv)));
    return;
  }
  case Shape::grid: {
    internal::check_positive(options.size, "size", "make_shape");
    const std::size_t n = (std::max<std::size_t>)(2, std::lround(std::sqrt(double(target))));
    make_planar_grid(out, n, n, options.size / std::sqrt(2.0), options.size / std::sqrt(2.0));
    return;
  }
  case Shape::lampshade: {
    Lampshade_options o;
    static_cast<Shell_options&>(o) = options;
    make_thin_lampshade(out, o);
    return;
  }
  case Shape::vase: make_thin_vase(out, options); return;
  case Shape::pot: {
    Pot_options o;
    static_cast<Shell_options&>(o) = options;
    make_thin_pot(out, o);
    return;
  }
  case Shape::u_fold: {
    U_fold_options o;
    static_cast<Shell_options&>(o) = options;
    make_u_fold(out, o);
    return;
  }
  case Shape::slab: {
    Slab_options o;
    static_cast<Shell_options&>(o) = options;
    make_thin_slab(out, o);
    return;
  }
  case Shape::bowl: make_thin_bowl(out, options); return;
  case Shape::box: {
    Box_options o;
    static_cast<Shell_options&>(o) = options;
    make_thin_walled_box(out, o);
    return;
  }
  }
  throw std::invalid_argument("make_shape: not a Shape value");
}

/// Refines `mesh` by `levels` steps of Loop subdivision (each multiplies the
/// number of faces by 4), for benchmarks at sizes the generators are not
/// asked for directly. Loop smoothing moves vertices: it rounds the sharp
/// rims of the thin shells and can bring their two wall sides closer, so
/// prefer a larger `target_vertices` when the wall geometry matters.
/// \throws std::invalid_argument if `levels < 0` or `mesh` is not a triangle mesh.
template <class TriangleMesh>
void loop_subdivide(TriangleMesh& mesh, int levels)
{
  if(levels < 0)
    throw std::invalid_argument("loop_subdivide: levels must be non-negative (got " + std::to_string(levels) + ")");
  if(levels == 0)
    return;
  if(!CGAL::is_triangle_mesh(mesh))
    throw std::invalid_argument("loop_subdivide: the mesh must be a triangle mesh");
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
}

} // namespace meshes
} // namespace svd_test

#endif // SVD_TEST_MESHES_H
