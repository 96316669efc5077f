// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Headless rendering of an arrangement into an image or a PNG file, for the manual's figures
// (make_figures.cpp, beside this file) and the tests; not part of the library. A software
// rasterizer (z-buffer, supersampling), Lambert + ambient shading, cells in the package's
// colours (CGAL::Surface_voronoi::site_color()), cell boundaries as dark lines and sites as
// dots. It needs no OpenGL and no window, so figures can be produced by the build.
//
// Lines are drawn by the faces themselves: each visible sample checks its distance, on the
// screen, to the boundary edges around its face. A line is thus depth-tested exactly by
// the z-buffer of the faces, with no depth bias to tune (thin walls stay thin).

#ifndef SVD_FIGURES_RENDER_PNG_H
#define SVD_FIGURES_RENDER_PNG_H

#include "PNG_writer.h"

#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace svd_figures {

/// Camera projection of `render_arrangement()`.
enum class Projection
{
  ORTHOGRAPHIC, ///< parallel projection (the default: sizes compare across the image)
  PERSPECTIVE   ///< pinhole camera at `Render_options::camera_distance` bounding radii from the centre
};

/// Options of `render_arrangement()` and `render_diagram()`. The camera is placed
/// automatically: it looks at the centre of the bounding box along `view_direction`, and the
/// mesh is scaled to fill the image up to `margin`.
struct Render_options
{
  std::size_t width = 640;              ///< image width in pixels (8 to 8192)
  std::size_t height = 480;             ///< image height in pixels (8 to 8192)
  /// the direction the camera looks in, in mesh coordinates (need not be unit)
  std::array<double, 3> view_direction = {{-1.0, -1.6, -1.1}};
  /// the direction shown upwards (projected orthogonally to the view direction; replaced by
  /// another axis when parallel to it)
  std::array<double, 3> up = {{0.0, 0.0, 1.0}};
  Projection projection = Projection::ORTHOGRAPHIC;
  /// distance from the camera to the bounding-box centre, in bounding-box radii (perspective; > 1)
  double camera_distance = 3.0;
  /// samples per pixel along each axis (1 to 4): 2 gives 2x2 anti-aliasing
  unsigned supersampling = 2;
  /// free border on each side, as a fraction of the image size (0 to 0.45)
  double margin = 0.04;
  /// share of the light that does not depend on the orientation (0 to 1); the rest is
  /// Lambertian, two-sided (so the inside of a shell is lit too)
  double ambient = 0.45;
  /// smooth shading across edges whose faces make an angle below this (degrees, 0 to 90);
  /// sharper edges, such as the rims of a thin wall, stay sharp (0: flat shading)
  double crease_angle = 40;
  CGAL::IO::Color background = CGAL::IO::Color(255, 255, 255);
  CGAL::IO::Color edge_color = CGAL::IO::Color(25, 25, 25);
  /// width of cell boundary lines in pixels (0: no lines)
  double edge_width = 1.5;
  /// also draw the border of the surface as a line
  bool draw_border = true;
  /// colour of the site dots
  CGAL::IO::Color site_dot_color = CGAL::IO::Color(15, 15, 15);
  /// radius of the site dots in pixels (0: no dots); a light ring makes them visible on dark cells
  double site_radius = 2.5;
};

namespace internal {

typedef std::array<double, 3> Render_vec;

inline Render_vec render_sub(const Render_vec& a, const Render_vec& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline double render_dot(const Render_vec& a, const Render_vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Render_vec render_cross(const Render_vec& a, const Render_vec& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline bool render_normalize(Render_vec& a)
{
  const double n = std::sqrt(render_dot(a, a));
  if(!(n > 0) || !std::isfinite(n)) return false;
  for(double& c : a) c /= n;
  return true;
}

inline void check_render_options(const Render_options& o)
{
  auto fail = [](const std::string& what) { throw Input_error("render_arrangement: " + what); };
  if(o.width < 8 || o.width > 8192 || o.height < 8 || o.height > 8192)
    fail("the image size must be between 8 and 8192 pixels each way (got " + std::to_string(o.width) + " x "
         + std::to_string(o.height) + ")");
  if(o.supersampling < 1 || o.supersampling > 4)
    fail("supersampling must be 1 to 4 (got " + std::to_string(o.supersampling) + ")");
  Render_vec f = o.view_direction;
  if(!render_normalize(f)) fail("the view direction must be a finite non-zero vector");
  if(!std::isfinite(o.up[0]) || !std::isfinite(o.up[1]) || !std::isfinite(o.up[2])) fail("the up vector must be finite");
  if(!(o.margin >= 0 && o.margin < 0.45)) fail("the margin must be in [0, 0.45)");
  if(!(o.ambient >= 0 && o.ambient <= 1)) fail("ambient must be in [0, 1]");
  if(!(o.crease_angle >= 0 && o.crease_angle <= 90)) fail("crease_angle must be in [0, 90] degrees");
  if(!(o.edge_width >= 0 && o.edge_width <= 64)) fail("edge_width must be in [0, 64] pixels");
  if(!(o.site_radius >= 0 && o.site_radius <= 256)) fail("site_radius must be in [0, 256] pixels");
  if(o.projection == Projection::PERSPECTIVE && !(o.camera_distance > 1 && std::isfinite(o.camera_distance)))
    fail("camera_distance must be finite and greater than 1 (the camera must be outside the bounding sphere)");
}

// Distance from (px, py) to the segment [a, b], squared.
inline double squared_segment_distance(double px, double py, const std::array<double, 4>& s)
{
  const double dx = s[2] - s[0], dy = s[3] - s[1], ex = px - s[0], ey = py - s[1];
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? (ex * dx + ey * dy) / l2 : 0;
  t = (std::max)(0.0, (std::min)(1.0, t));
  const double rx = ex - t * dx, ry = ey - t * dy;
  return rx * rx + ry * ry;
}

} // namespace internal

/// Renders a polygon mesh whose faces are labelled by site, typically the arrangement written
/// by `make_arrangement()`, into an RGB image: faces are filled with the colour of their
/// cell, `CGAL::Surface_voronoi::site_color()` (grey for a negative site: no site reaches it),
/// shaded with ambient and two-sided Lambertian light from the upper left of the camera;
/// constrained edges (cell boundaries) are dark lines hidden where the surface hides them;
/// `sites` are dots, drawn where they are not hidden. The result is deterministic.
///
/// \tparam PolygonMesh a model of `FaceListGraph` (faces may be any planar polygons)
/// \tparam FaceSiteMap a readable property map from faces to an integral site index
/// \tparam PointRange a range of points with `x()`, `y()`, `z()` (may be empty)
/// \param mesh the mesh to draw
/// \param face_site the site of every face
/// \param sites the points drawn as dots
/// \param options image size, camera, colours and line widths
/// \param np optional named parameters: `vertex_point_map`; `edge_is_constrained_map` (a
///        readable map edge -> `bool`, the lines drawn; default: the edges between faces of
///        different sites)
/// \returns the image, `options.width` x `options.height`
/// \throws Input_error on invalid options, an empty mesh, a non-finite coordinate, or a mesh
///         that projects to a single point
template <class PolygonMesh, class FaceSiteMap, class PointRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Image render_arrangement(const PolygonMesh& mesh, FaceSiteMap face_site, const PointRange& sites,
                         const Render_options& options = Render_options(),
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using internal::Render_vec;
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  internal::check_render_options(options);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
  const bool has_constraints = !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value;
  auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                      CGAL::Constant_property_map<edge_descriptor, bool>(false));

  // vertices and faces as indices
  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  std::vector<Render_vec> positions;
  for(vertex_descriptor v : vertices(mesh))
  {
    put(vid, v, positions.size());
    const auto& p = get(vpm, v);
    const Render_vec q = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw Input_error("render_arrangement: vertex " + std::to_string(positions.size()) + " has a non-finite coordinate");
    positions.push_back(q);
  }
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::int64_t> face_sites;
  auto fid = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  for(face_descriptor f : faces(mesh))
  {
    put(fid, f, polygons.size());
    polygons.emplace_back();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) polygons.back().push_back(get(vid, v));
    face_sites.push_back(static_cast<std::int64_t>(get(face_site, f)));
  }
  if(polygons.empty()) throw Input_error("render_arrangement: the mesh has no face");

  // lines: the chosen edges (or the cell boundaries), and the border
  std::vector<std::array<std::size_t, 2> > lines;
  for(edge_descriptor e : edges(mesh))
  {
    const halfedge_descriptor h = halfedge(e, mesh), o = opposite(h, mesh);
    const bool border = is_border(h, mesh) || is_border(o, mesh);
    const bool line = border ? options.draw_border
                             : has_constraints ? bool(get(constrained, e))
                                               : face_sites[get(fid, face(h, mesh))] != face_sites[get(fid, face(o, mesh))];
    if(line) lines.push_back({{get(vid, source(h, mesh)), get(vid, target(h, mesh))}});
  }
  std::vector<CGAL::IO::Color> face_colors;   // the package's colour of each face's site
  face_colors.reserve(face_sites.size());
  for(std::int64_t site : face_sites) face_colors.push_back(CGAL::Surface_voronoi::site_color(site));

  // camera frame: `right` and `upward` span the image plane, `forward` points into the scene
  Render_vec forward = options.view_direction;
  internal::render_normalize(forward);
  Render_vec upward = options.up;
  Render_vec right = internal::render_cross(forward, upward);
  if(!internal::render_normalize(right) || std::abs(internal::render_dot(forward, upward)) > 0.999 * std::sqrt(internal::render_dot(upward, upward)))
  {
    // up parallel to the view (or zero): take the coordinate axis most orthogonal to it
    int k = 0;
    for(int c = 1; c < 3; ++c)
      if(std::abs(forward[c]) < std::abs(forward[k])) k = c;
    upward = {{0, 0, 0}};
    upward[k] = 1;
    right = internal::render_cross(forward, upward);
    internal::render_normalize(right);
  }
  upward = internal::render_cross(right, forward);

  Render_vec lo = positions[polygons[0][0]], hi = lo;
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      for(int c = 0; c < 3; ++c)
      {
        lo[c] = (std::min)(lo[c], positions[v][c]);
        hi[c] = (std::max)(hi[c], positions[v][c]);
      }
  const Render_vec centre = {{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}};
  const double radius = std::sqrt(internal::render_dot(internal::render_sub(hi, lo), internal::render_sub(hi, lo))) / 2;
  if(!(radius > 0)) throw Input_error("render_arrangement: all vertices of the mesh are at one point");
  const bool perspective = options.projection == Projection::PERSPECTIVE;
  const double eye_distance = options.camera_distance * radius;

  // projection to the image plane, with a `nearness` that grows towards the camera and is
  // affine in screen space (minus the depth, or the inverse depth in perspective)
  struct Projected { double x, y, nearness; };
  auto project = [&](const Render_vec& p) {
    const Render_vec d = internal::render_sub(p, centre);
    const double x = internal::render_dot(d, right), y = internal::render_dot(d, upward), z = internal::render_dot(d, forward);
    if(!perspective) return Projected{x, y, -z};
    const double depth = z + eye_distance;
    return Projected{x / depth, y / depth, 1 / depth};
  };
  std::vector<Projected> projected(positions.size());
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
    {
      projected[v] = project(positions[v]);
      xmin = (std::min)(xmin, projected[v].x); xmax = (std::max)(xmax, projected[v].x);
      ymin = (std::min)(ymin, projected[v].y); ymax = (std::max)(ymax, projected[v].y);
    }
  const double tiny = 1e-12 * (perspective ? 1.0 : radius);
  if(xmax - xmin <= tiny && ymax - ymin <= tiny)
    throw Input_error("render_arrangement: the mesh projects to a single point along the view direction");

  // samples: the image at `ss` x `ss` resolution; sample (i, j) has its centre at (i + 0.5, j + 0.5)
  const std::size_t ss = options.supersampling, W = options.width * ss, H = options.height * ss;
  const double usable_w = double(W) * (1 - 2 * options.margin), usable_h = double(H) * (1 - 2 * options.margin);
  double scale = std::numeric_limits<double>::infinity();
  if(xmax - xmin > tiny) scale = usable_w / (xmax - xmin);
  if(ymax - ymin > tiny) scale = (std::min)(scale, usable_h / (ymax - ymin));
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  auto to_sample_x = [&](double x) { return double(W) / 2 + (x - cx) * scale; };
  auto to_sample_y = [&](double y) { return double(H) / 2 - (y - cy) * scale; };
  std::vector<std::array<double, 3> > screen(positions.size());
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      screen[v] = {{to_sample_x(projected[v].x), to_sample_y(projected[v].y), projected[v].nearness}};

  // shading: two-sided Lambert with a light above, left of and behind the camera, evaluated
  // at the corners of every face with the normal averaged over the faces around the corner
  // that are within the crease angle, and interpolated across the face
  Render_vec light = {{0, 0, 0}};
  for(int c = 0; c < 3; ++c) light[c] = -0.9 * forward[c] + 0.4 * upward[c] - 0.25 * right[c];
  internal::render_normalize(light);
  std::vector<Render_vec> area_normal(polygons.size()), unit_normal(polygons.size());
  std::vector<std::vector<std::size_t> > faces_at_vertex(positions.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    Render_vec normal = {{0, 0, 0}};   // Newell's normal: twice the area, for any planar polygon
    const auto& polygon = polygons[f];
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      const Render_vec& p = positions[polygon[k]];
      const Render_vec& q = positions[polygon[(k + 1) % polygon.size()]];
      normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
      normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
      normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
      faces_at_vertex[polygon[k]].push_back(f);
    }
    area_normal[f] = unit_normal[f] = normal;
    if(!internal::render_normalize(unit_normal[f])) unit_normal[f] = {{0, 0, 0}};
  }
  const double cos_crease = std::cos(options.crease_angle * 3.14159265358979323846 / 180);
  std::vector<std::size_t> first_corner(polygons.size() + 1, 0);
  for(std::size_t f = 0; f < polygons.size(); ++f) first_corner[f + 1] = first_corner[f] + polygons[f].size();
  std::vector<double> corner_light(first_corner.back());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = 0; k < polygons[f].size(); ++k)
    {
      Render_vec normal = unit_normal[f];
      if(options.crease_angle > 0)
      {
        normal = {{0, 0, 0}};
        for(std::size_t g : faces_at_vertex[polygons[f][k]])
          if(g == f || internal::render_dot(unit_normal[g], unit_normal[f]) >= cos_crease)
            for(int c = 0; c < 3; ++c) normal[c] += area_normal[g][c];
      }
      const double lambert = internal::render_normalize(normal) ? std::abs(internal::render_dot(normal, light)) : 1.0;
      corner_light[first_corner[f] + k] = options.ambient + (1 - options.ambient) * lambert;
    }

  // z-buffer pass: the nearest face of every sample, and its light there
  std::vector<double> nearness(W * H, -std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> owner(W * H, -1);
  std::vector<float> shade(W * H, 1.f);
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const auto& polygon = polygons[f];
    for(std::size_t k = 1; k + 1 < polygon.size(); ++k)
    {
      const auto& a = screen[polygon[0]];
      const auto& b = screen[polygon[k]];
      const auto& c = screen[polygon[k + 1]];
      const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if(!(std::abs(area) > 1e-12)) continue;   // seen edge-on
      const double x0 = (std::max)(0.0, std::floor((std::min)({a[0], b[0], c[0]})));
      const double x1 = (std::min)(double(W) - 1, std::ceil((std::max)({a[0], b[0], c[0]})));
      const double y0 = (std::max)(0.0, std::floor((std::min)({a[1], b[1], c[1]})));
      const double y1 = (std::min)(double(H) - 1, std::ceil((std::max)({a[1], b[1], c[1]})));
      for(double y = y0; y <= y1; ++y)
        for(double x = x0; x <= x1; ++x)
        {
          const double px = x + 0.5, py = y + 0.5;
          // barycentric coordinates; a sample on a shared edge may go to either face
          const double wa = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
          const double wb = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
          const double wc = 1 - wa - wb;
          if(wa < 0 || wb < 0 || wc < 0) continue;
          const double n = wa * a[2] + wb * b[2] + wc * c[2];
          const std::size_t s = std::size_t(y) * W + std::size_t(x);
          if(n > nearness[s])
          {
            nearness[s] = n;
            owner[s] = std::int64_t(f);
            shade[s] = float(wa * corner_light[first_corner[f]] + wb * corner_light[first_corner[f] + k]
                             + wc * corner_light[first_corner[f] + k + 1]);
          }
        }
    }
  }

  // the lines each face may show: those touching one of its vertices (so line ends and
  // corners are drawn completely by the faces around them)
  std::vector<std::vector<std::size_t> > lines_at_vertex(positions.size());
  std::vector<std::array<double, 4> > segments;
  for(const auto& l : lines)
  {
    lines_at_vertex[l[0]].push_back(segments.size());
    lines_at_vertex[l[1]].push_back(segments.size());
    segments.push_back({{screen[l[0]][0], screen[l[0]][1], screen[l[1]][0], screen[l[1]][1]}});
  }
  const double half_width = options.edge_width * double(ss) / 2;
  std::vector<double> samples(3 * W * H);
  std::vector<std::size_t> near_lines;
  std::int64_t near_lines_of = -1;
  for(std::size_t y = 0; y < H; ++y)
    for(std::size_t x = 0; x < W; ++x)
    {
      const std::size_t s = y * W + x;
      const std::int64_t f = owner[s];
      std::array<double, 3> rgb = {{double(options.background.red()), double(options.background.green()),
                                    double(options.background.blue())}};
      if(f >= 0)
      {
        const CGAL::IO::Color& color = face_colors[std::size_t(f)];
        rgb = {{shade[s] * color.red(), shade[s] * color.green(), shade[s] * color.blue()}};
        if(half_width > 0)
        {
          if(near_lines_of != f)
          {
            near_lines.clear();
            for(std::size_t v : polygons[std::size_t(f)])
              near_lines.insert(near_lines.end(), lines_at_vertex[v].begin(), lines_at_vertex[v].end());
            near_lines_of = f;
          }
          for(std::size_t l : near_lines)
            if(internal::squared_segment_distance(x + 0.5, y + 0.5, segments[l]) <= half_width * half_width)
            {
              rgb = {{double(options.edge_color.red()), double(options.edge_color.green()), double(options.edge_color.blue())}};
              break;
            }
        }
      }
      for(int c = 0; c < 3; ++c) samples[3 * s + c] = rgb[c];
    }

  // sites: a dot with a light ring, where the surface does not hide the site
  const double dot = options.site_radius * double(ss), ring = dot + 0.9 * double(ss);
  double near_min = std::numeric_limits<double>::infinity(), near_max = -near_min;
  for(const auto& polygon : polygons)   // vertices of faces only: isolated ones were not projected
    for(std::size_t v : polygon)
    {
      near_min = (std::min)(near_min, screen[v][2]);
      near_max = (std::max)(near_max, screen[v][2]);
    }
  const double tolerance = 1e-4 * (near_max - near_min);
  if(dot > 0)
    for(const auto& p : sites)
    {
      const Projected q = project({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
      const double sx = to_sample_x(q.x), sy = to_sample_y(q.y);
      if(!(sx >= 0 && sy >= 0 && sx < double(W) && sy < double(H))) continue;
      // visible if not behind the farthest surface among the samples around it: the site
      // is on the surface, whose depth varies across a sample, but a wall in front is farther
      double lowest = std::numeric_limits<double>::infinity();
      const std::int64_t ix = std::int64_t(sx), iy = std::int64_t(sy);
      for(std::int64_t j = iy - 1; j <= iy + 1; ++j)
        for(std::int64_t i = ix - 1; i <= ix + 1; ++i)
          if(i >= 0 && j >= 0 && i < std::int64_t(W) && j < std::int64_t(H) && owner[std::size_t(j) * W + std::size_t(i)] >= 0)
            lowest = (std::min)(lowest, nearness[std::size_t(j) * W + std::size_t(i)]);
      if(std::isfinite(lowest) && q.nearness < lowest - tolerance) continue;
      for(std::int64_t j = std::int64_t(sy - ring) - 1; j <= std::int64_t(sy + ring) + 1; ++j)
        for(std::int64_t i = std::int64_t(sx - ring) - 1; i <= std::int64_t(sx + ring) + 1; ++i)
        {
          if(i < 0 || j < 0 || i >= std::int64_t(W) || j >= std::int64_t(H)) continue;
          const double r = std::hypot(double(i) + 0.5 - sx, double(j) + 0.5 - sy);
          if(r > ring) continue;
          const std::size_t s = std::size_t(j) * W + std::size_t(i);
          const CGAL::IO::Color c = r <= dot ? options.site_dot_color : CGAL::IO::Color(250, 250, 250);
          samples[3 * s] = c.red(); samples[3 * s + 1] = c.green(); samples[3 * s + 2] = c.blue();
        }
    }

  // box filter down to the image
  Image image(options.width, options.height);
  for(std::size_t y = 0; y < options.height; ++y)
    for(std::size_t x = 0; x < options.width; ++x)
      for(int c = 0; c < 3; ++c)
      {
        double sum = 0;
        for(std::size_t j = 0; j < ss; ++j)
          for(std::size_t i = 0; i < ss; ++i) sum += samples[3 * ((y * ss + j) * W + x * ss + i) + c];
        image.rgb[3 * (y * options.width + x) + c] =
            static_cast<unsigned char>((std::min)(255.0, std::floor(sum / double(ss * ss) + 0.5)));
      }
  return image;
}

/// Renders `diagram`: its arrangement (`make_arrangement()`) with cell boundaries and
/// breaklines as lines, and its sites as dots. See `render_arrangement()`.
/// \throws Input_error on invalid options
template <class Diagram>
Image render_diagram(const Diagram& diagram, const Render_options& options = Render_options())
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh out;
  auto site = out.add_property_map<Mesh::Face_index, std::int64_t>("f:site", -1).first;
  auto boundary = out.add_property_map<Mesh::Edge_index, bool>("e:boundary", false).first;
  CGAL::Surface_voronoi::make_arrangement(diagram, out,
                                          CGAL::parameters::face_patch_map(site).edge_is_constrained_map(boundary));
  std::vector<Point> sites;
  for(std::size_t i = 0; i < diagram.number_of_sites(); ++i)
  {
    const auto p = diagram.site_point(i);
    sites.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  return render_arrangement(out, site, sites, options, CGAL::parameters::edge_is_constrained_map(boundary));
}

/// Renders `diagram` (see `render_diagram()`) and writes the image to `filename` as a PNG.
/// \throws Input_error on invalid options
/// \throws Write_error if the file cannot be written
template <class Diagram>
void render_PNG(const std::string& filename, const Diagram& diagram, const Render_options& options = Render_options())
{
  write_PNG(filename, render_diagram(diagram, options));
}

} // namespace svd_figures

#endif // SVD_FIGURES_RENDER_PNG_H
