// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Interactive viewing of a diagram with CGAL's Basic_viewer_qt, in the style of CGAL's own
// draw() functions. The viewer needs Qt5 (Debian: libcgal-qt5-dev) and is enabled by
// linking CGAL::CGAL_Basic_viewer, which defines CGAL_USE_BASIC_VIEWER. Without it this
// header includes nothing from Qt and draw() only prints a message, so code calling draw()
// still compiles and runs everywhere.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H

#ifdef DOXYGEN_RUNNING

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Opens a window showing `diagram`: its arrangement with one colour per cell (neighbouring
/// cells differ, the colours of `IO::render_diagram()`), cell boundaries and breaklines as
/// black segments, and the sites as black points. The function blocks until the window is
/// closed. It requires Qt5 and is only available if the macro `CGAL_USE_BASIC_VIEWER` is
/// defined, which linking with the CMake target `CGAL::CGAL_Basic_viewer` does; otherwise it
/// prints an error message and returns. When `CGAL_TEST_SUITE` is defined (as a macro or an
/// environment variable) it returns at once and opens no window.
/// \tparam Diagram a `CGAL::Surface_voronoi_diagram`
/// \param diagram the diagram to draw
/// \param title the title of the window
template <class Diagram>
void draw(const Diagram& diagram, const char* title = "Surface Voronoi diagram");

} // namespace Surface_voronoi
} // namespace CGAL

#else // DOXYGEN_RUNNING

#include <iostream>

#ifdef CGAL_USE_BASIC_VIEWER

#include <CGAL/Qt/Basic_viewer_qt.h>
#include <CGAL/Qt/init_ogl_context.h>
#include <CGAL/Surface_voronoi_diagram/IO/render_PNG.h>
#include <CGAL/Surface_voronoi_diagram/arrangement.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {

/// The viewer behind `draw()`: the arrangement, its boundaries and the sites, coloured as by
/// `IO::render_diagram()`. It owns a copy of everything it shows.
class Diagram_viewer_qt : public CGAL::Basic_viewer_qt
{
  typedef CGAL::Basic_viewer_qt Base;

public:
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Mesh;

  template <class Diagram>
  Diagram_viewer_qt(QWidget* parent, const Diagram& diagram, const char* title)
    // points, edges and faces drawn; per-face colours; normals as computed
    : Base(parent, title, true, true, true, false, false)
  {
    m_site = m_arrangement.add_property_map<Mesh::Face_index, std::int64_t>("f:site", -1).first;
    m_boundary = m_arrangement.add_property_map<Mesh::Edge_index, bool>("e:boundary", false).first;
    make_arrangement(diagram, m_arrangement, CGAL::parameters::face_patch_map(m_site).edge_is_constrained_map(m_boundary));
    for(std::size_t i = 0; i < diagram.number_of_sites(); ++i)
    {
      const auto p = diagram.site_point(i);
      m_sites.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    m_colors = IO::internal::color_cells(IO::internal::cell_adjacency(m_arrangement, m_site), IO::internal::default_palette());
    compute_elements();
  }

protected:
  void compute_elements()
  {
    clear();
    for(Mesh::Face_index f : m_arrangement.faces())
    {
      const std::int64_t s = m_site[f];
      face_begin(s < 0 ? CGAL::IO::Color(190, 190, 190) : m_colors.at(s));
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(m_arrangement.halfedge(f), m_arrangement))
        add_point_in_face(m_arrangement.point(v));
      face_end();
    }
    for(Mesh::Edge_index e : m_arrangement.edges())
      if(m_boundary[e] || m_arrangement.is_border(e))
        add_segment(m_arrangement.point(m_arrangement.vertex(e, 0)), m_arrangement.point(m_arrangement.vertex(e, 1)),
                    CGAL::IO::Color(20, 20, 20));
    for(const Point& p : m_sites) add_point(p, CGAL::IO::Color(10, 10, 10));
  }

private:
  Mesh m_arrangement;
  Mesh::Property_map<Mesh::Face_index, std::int64_t> m_site;
  Mesh::Property_map<Mesh::Edge_index, bool> m_boundary;
  std::vector<Point> m_sites;
  std::map<std::int64_t, CGAL::IO::Color> m_colors;
};

template <class Diagram>
void draw(const Diagram& diagram, const char* title = "Surface Voronoi diagram")
{
#if defined(CGAL_TEST_SUITE)
  const bool test_suite = true;
#else
  const bool test_suite = qEnvironmentVariableIsSet("CGAL_TEST_SUITE");
#endif
  if(test_suite) return;   // never a window in a test run
  CGAL::Qt::init_ogl_context(4, 3);
  int argc = 1;
  const char* argv[2] = {"surface_voronoi_viewer", nullptr};
  QApplication app(argc, const_cast<char**>(argv));
  Diagram_viewer_qt viewer(app.activeWindow(), diagram, title);
  viewer.show();
  app.exec();
}

} // namespace Surface_voronoi
} // namespace CGAL

#else // CGAL_USE_BASIC_VIEWER

namespace CGAL {
namespace Surface_voronoi {

// Without Qt: a message, like CGAL's own draw() functions, and no window.
template <class Diagram>
void draw(const Diagram&, const char* = "")
{
  std::cerr << "Impossible to draw, CGAL_USE_BASIC_VIEWER is not defined (link with CGAL::CGAL_Basic_viewer)."
            << std::endl;
}

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_USE_BASIC_VIEWER

#endif // DOXYGEN_RUNNING

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H
