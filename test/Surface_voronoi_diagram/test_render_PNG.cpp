// The headless renderer and the PNG writer of the manual's figures
// (doc/Surface_voronoi_diagram/figures/): image size, background, cells in the package's
// colours (site_color()), lines, hidden sites, determinism, bad input, and a well-formed PNG
// stream.
#include "test_support.h"

#include <CGAL/Surface_voronoi_diagram/Euclidean_embedding.h>
#include <test_meshes.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <render_PNG.h>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_render_PNG {

using namespace svd_test;
namespace SV = CGAL::Surface_voronoi;
namespace SVF = svd_figures;
namespace GEN = svd_test::meshes;
typedef SV::Euclidean_embedding<Mesh> Euclidean;
typedef std::array<unsigned char, 3> RGB;

namespace {

// the unit square seen from above, x to the right and y up, filling the image
SVF::Render_options top_view(std::size_t w, std::size_t h)
{
  SVF::Render_options o;
  o.width = w;
  o.height = h;
  o.view_direction = {{0, 0, -1}};
  o.up = {{0, 1, 0}};
  o.margin = 0.1;
  return o;
}

RGB white() { return {{255, 255, 255}}; }

// whether `pixel` is `color` under some shade in (0, 1] (light scales the three channels alike)
bool is_shaded(const RGB& pixel, const CGAL::IO::Color& color)
{
  const double c[3] = {double(color.red()), double(color.green()), double(color.blue())};
  const double shade = (pixel[0] * c[0] + pixel[1] * c[1] + pixel[2] * c[2]) / (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  bool close = shade > 0 && shade <= 1.01;
  for(int k = 0; k < 3; ++k) close = close && std::abs(pixel[k] - shade * c[k]) <= 2.5;
  return close;
}

std::uint32_t big_endian(const std::vector<unsigned char>& b, std::size_t at)
{
  return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) | (std::uint32_t(b[at + 2]) << 8) | b[at + 3];
}

} // namespace

TEST_CASE("render: two cells of a square get their sites' colours, the background stays white", "[render]")
{
  Mesh m;
  GEN::make_planar_grid(m, 11, 11, 1.0, 1.0);
  Euclidean e(m);
  const std::vector<Point> sites = {Point(0.25, 0.5, 0), Point(0.75, 0.5, 0)};
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> vd(m, e, sites);
  SVF::Render_options o = top_view(200, 100);
  const SVF::Image image = SVF::render_diagram(vd, o);
  REQUIRE(image.width == 200);
  REQUIRE(image.height == 100);
  REQUIRE(image.rgb.size() == 3 * 200 * 100);
  // the square is 80 pixels tall (10% margins), centred: x in [60, 140], y in [10, 90]
  CHECK(image.pixel(0, 0) == white());
  CHECK(image.pixel(199, 99) == white());
  CHECK(image.pixel(30, 50) == white());
  CHECK(image.pixel(170, 50) == white());
  const RGB left = image.pixel(70, 30), right = image.pixel(130, 30);
  CHECK(left != white());
  CHECK(right != white());
  CHECK(left != right);
  // the package's colour scheme: site 0 on the left, site 1 on the right
  CHECK(is_shaded(left, SV::site_color(0)));
  CHECK(is_shaded(right, SV::site_color(1)));
  CHECK_FALSE(is_shaded(left, SV::site_color(1)));
  // the bisector x = 0.5 is a dark line at x = 100
  const RGB line = image.pixel(100, 30);
  CHECK(int(line[0]) + line[1] + line[2] < 3 * 80);
  // a site dot at (0.25, 0.5) -> pixel (80, 50)
  const RGB dot = image.pixel(80, 50);
  CHECK(int(dot[0]) + dot[1] + dot[2] < 3 * 80);
  // the same picture every time
  CHECK(SVF::render_diagram(vd, o).rgb == image.rgb);

  // no lines, no dots: the cell colour reaches the bisector and the site
  o.edge_width = 0;
  o.site_radius = 0;
  const SVF::Image plain = SVF::render_diagram(vd, o);
  CHECK(plain.pixel(80, 50) == left);
  CHECK(plain.pixel(98, 30) == left);
  CHECK(plain.pixel(102, 30) == right);
}

TEST_CASE("render: a site behind the surface is hidden", "[render]")
{
  Mesh m;
  GEN::make_icosphere(m, 3, 1.0);
  Euclidean e(m);
  SVF::Render_options o = top_view(120, 120);   // looks down -z: z = 1 is in front
  // sites on the axis: front (0, 0, 1), back (0, 0, -1); both project to the centre
  const std::vector<Point> both = {Point(0, 0, 1), Point(0, 0, -1)}, back_first = {Point(0, 0, -1), Point(0.6, 0, -0.8)};
  CGAL::Surface_voronoi_diagram<Mesh, Euclidean> front(m, e, both), back(m, e, back_first);
  const RGB with_front = SVF::render_diagram(front, o).pixel(60, 60);
  const RGB hidden = SVF::render_diagram(back, o).pixel(60, 60);
  CHECK(int(with_front[0]) + with_front[1] + with_front[2] < 3 * 80);   // dot
  CHECK(int(hidden[0]) + hidden[1] + hidden[2] > 3 * 80);               // cell colour, no dot
  CHECK(hidden != white());
}

TEST_CASE("render: any face graph, explicit line map, perspective", "[render]")
{
  Mesh m;
  GEN::make_planar_grid(m, 5, 5, 1.0, 1.0);
  Polyhedron p;
  CGAL::copy_face_graph(m, p);
  SVF::Render_options o = top_view(64, 64);
  o.projection = SVF::Projection::PERSPECTIVE;
  const std::vector<Point> none;
  const SVF::Image all_edges = SVF::render_arrangement(
      p, CGAL::Constant_property_map<Polyhedron::Face_handle, int>(0), none, o,
      CGAL::parameters::edge_is_constrained_map(CGAL::Constant_property_map<boost::graph_traits<Polyhedron>::edge_descriptor, bool>(true)));
  const SVF::Image no_edges = SVF::render_arrangement(p, CGAL::Constant_property_map<Polyhedron::Face_handle, int>(0), none, o);
  CHECK(all_edges.pixel(0, 0) == white());
  const RGB lit = no_edges.pixel(32, 20);   // site 0's colour (242, 198, 133), shaded
  CHECK(lit != white());
  CHECK(is_shaded(lit, SV::site_color(0)));
  CHECK(lit[0] > lit[1]);
  CHECK(lit[1] > lit[2]);
  CHECK(lit[0] > 150);
  std::size_t dark = 0;
  for(std::size_t k = 0; k < 64 * 64; ++k) dark += all_edges.rgb[3 * k] < 100;
  CHECK(dark > 200);   // the grid lines
  CHECK(all_edges.rgb != no_edges.rgb);
}

TEST_CASE("render: bad input throws with a message", "[render]")
{
  Mesh m;
  GEN::make_planar_grid(m, 3, 3, 1.0, 1.0);
  auto site = CGAL::Constant_property_map<Mesh::Face_index, int>(0);
  const std::vector<Point> none;
  SVF::Render_options o;
  o.width = 0;
  CHECK_THROWS_AS(SVF::render_arrangement(m, site, none, o), SVF::Input_error);
  o = SVF::Render_options();
  o.height = 100000;
  CHECK_THROWS_AS(SVF::render_arrangement(m, site, none, o), SVF::Input_error);
  o = SVF::Render_options();
  o.supersampling = 0;
  CHECK_THROWS_AS(SVF::render_arrangement(m, site, none, o), SVF::Input_error);
  o = SVF::Render_options();
  o.view_direction = {{0, 0, 0}};
  CHECK_THROWS_WITH(SVF::render_arrangement(m, site, none, o), Catch::Contains("view direction"));
  o = SVF::Render_options();
  o.projection = SVF::Projection::PERSPECTIVE;
  o.camera_distance = 0.5;
  CHECK_THROWS_AS(SVF::render_arrangement(m, site, none, o), SVF::Input_error);
  // an empty mesh, and a triangle with its three corners at one point
  Mesh empty;
  CHECK_THROWS_WITH(SVF::render_arrangement(empty, site, none), Catch::Contains("no face"));
  Mesh point;
  const auto a = point.add_vertex(Point(1, 1, 1)), b = point.add_vertex(Point(1, 1, 1)), c = point.add_vertex(Point(1, 1, 1));
  point.add_face(a, b, c);
  CHECK_THROWS_WITH(SVF::render_arrangement(point, site, none), Catch::Contains("one point"));
  // a non-finite coordinate is named
  Mesh bad;
  GEN::make_planar_grid(bad, 3, 3, 1.0, 1.0);
  bad.point(Mesh::Vertex_index(4)) = Point(std::nan(""), 0, 0);
  CHECK_THROWS_WITH(SVF::render_arrangement(bad, site, none), Catch::Contains("vertex 4"));
  // seen edge-on, the square is a segment: drawn (as nothing), not an error
  o = SVF::Render_options();
  o.view_direction = {{1, 0, 0}};
  const SVF::Image edge_on = SVF::render_arrangement(m, site, none, o);
  CHECK(edge_on.width == 640);
  CHECK_THROWS_AS(SVF::encode_PNG(SVF::Image()), SVF::Input_error);
  CHECK_THROWS_AS(SVF::write_PNG("/nonexistent-dir/x.png", edge_on), SVF::Write_error);
}

TEST_CASE("PNG: signature, header, chunk CRCs and zlib checksum", "[render][io]")
{
  SVF::Image image(37, 5, {{10, 20, 30}});
  image.set_pixel(3, 2, {{200, 0, 0}});
  const std::vector<unsigned char> png = SVF::encode_PNG(image);
  const std::vector<unsigned char> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  REQUIRE(std::equal(signature.begin(), signature.end(), png.begin()));
  std::size_t at = 8;
  std::vector<std::string> types;
  std::vector<unsigned char> idat;
  while(at < png.size())
  {
    const std::uint32_t length = big_endian(png, at);
    REQUIRE(at + 12 + length <= png.size());
    types.emplace_back(png.begin() + at + 4, png.begin() + at + 8);
    const std::uint32_t crc = SVF::internal::crc32_update(0xFFFFFFFFu, png.data() + at + 4, length + 4) ^ 0xFFFFFFFFu;
    CHECK(crc == big_endian(png, at + 8 + length));
    if(types.back() == "IHDR")
    {
      CHECK(big_endian(png, at + 8) == 37);
      CHECK(big_endian(png, at + 12) == 5);
      CHECK(png[at + 16] == 8);   // bit depth
      CHECK(png[at + 17] == 2);   // RGB
    }
    if(types.back() == "IDAT") idat.assign(png.begin() + at + 8, png.begin() + at + 8 + length);
    at += 12 + length;
  }
  CHECK(types == std::vector<std::string>{"IHDR", "IDAT", "IEND"});
  // zlib header, and the Adler-32 of the filtered rows at the end
  REQUIRE(idat.size() > 6);
  CHECK((idat[0] * 256 + idat[1]) % 31 == 0);
  std::vector<unsigned char> raw;
  for(std::size_t y = 0; y < image.height; ++y)
  {
    raw.push_back(0);
    raw.insert(raw.end(), image.rgb.begin() + 3 * y * image.width, image.rgb.begin() + 3 * (y + 1) * image.width);
  }
  CHECK(SVF::internal::adler32(raw) == big_endian(idat, idat.size() - 4));
  // flat colour compresses
  CHECK(idat.size() < raw.size() / 4);
  // CRC-32 of "123456789" is the standard check value
  const std::string check = "123456789";
  CHECK((SVF::internal::crc32_update(0xFFFFFFFFu, reinterpret_cast<const unsigned char*>(check.data()), 9) ^ 0xFFFFFFFFu)
        == 0xCBF43926u);
}

} // namespace svd_test_render_PNG
