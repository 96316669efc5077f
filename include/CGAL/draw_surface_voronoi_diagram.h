// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// All rights reserved.
//
// This file is part of the Surface_voronoi_diagram package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : The Surface_voronoi_diagram authors
//
// Interactive viewing of a diagram with CGAL's Basic_viewer_qt, as CGAL's own draw_*.h
// headers do for their classes. The viewer needs Qt5 (Debian: libcgal-qt5-dev) and is enabled
// by linking CGAL::CGAL_Basic_viewer, which defines CGAL_USE_BASIC_VIEWER. Without it this
// header includes nothing from Qt and draw() only prints a message, so code calling draw()
// still compiles and runs everywhere.

#ifndef CGAL_DRAW_SURFACE_VORONOI_DIAGRAM_H
#define CGAL_DRAW_SURFACE_VORONOI_DIAGRAM_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram.h>

#ifdef DOXYGEN_RUNNING

namespace CGAL {

/// \ingroup PkgSurfaceVoronoiDiagramOutputs
/// Opens a window showing `diagram`: its arrangement with each cell in its colour
/// (`Surface_voronoi::site_color()`, the colours of the program's PLY files), cell boundaries
/// and breaklines as black segments, and the sites as black points. The function blocks until
/// the window is closed. It requires Qt5 and is only available if the macro
/// `CGAL_USE_BASIC_VIEWER` is defined, which linking with the CMake target
/// `CGAL::CGAL_Basic_viewer` does; otherwise it prints an error message and returns. When
/// `CGAL_TEST_SUITE` is defined (as a macro or an environment variable) it returns at once and
/// opens no window.
///
/// Include `<CGAL/draw_surface_voronoi_diagram.h>`.
/// \param diagram the diagram to draw
/// \param title the title of the window
template <class TriangleMesh, class Metric, class VertexPointMap, class GeomTraits, class ConcurrencyTag>
void draw(const Surface_voronoi_diagram<TriangleMesh, Metric, VertexPointMap, GeomTraits, ConcurrencyTag>& diagram,
          const char* title = "Surface Voronoi diagram");

} // namespace CGAL

#else // DOXYGEN_RUNNING

#include <iostream>

#ifdef CGAL_USE_BASIC_VIEWER

#include <CGAL/Qt/Basic_viewer_qt.h>
#include <CGAL/Qt/init_ogl_context.h>
#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/site_colors.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_voronoi {
namespace internal {

// The viewer behind draw(): the arrangement in the cell colours, its boundaries and the
// sites. It owns a copy of everything it shows.
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
    make_arrangement(diagram, m_arrangement,
                     CGAL::parameters::face_patch_map(m_site).edge_is_constrained_map(m_boundary));
    for(std::size_t i = 0; i < diagram.number_of_sites(); ++i)
    {
      const auto p = diagram.site_point(i);
      m_sites.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    compute_elements();
  }

protected:
  void compute_elements()
  {
    clear();
    for(Mesh::Face_index f : m_arrangement.faces())
    {
      face_begin(site_color(m_site[f]));
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
};

} // namespace internal
} // namespace Surface_voronoi

template <class... DiagramParameters>
void draw(const Surface_voronoi_diagram<DiagramParameters...>& diagram, const char* title = "Surface Voronoi diagram")
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
  Surface_voronoi::internal::Diagram_viewer_qt viewer(app.activeWindow(), diagram, title);
  viewer.show();
  app.exec();
}

} // namespace CGAL

#else // CGAL_USE_BASIC_VIEWER

namespace CGAL {

// Without Qt: a message, like CGAL's own draw() functions, and no window.
template <class... DiagramParameters>
void draw(const Surface_voronoi_diagram<DiagramParameters...>&, const char* = "")
{
  std::cerr << "Impossible to draw, CGAL_USE_BASIC_VIEWER is not defined (link with CGAL::CGAL_Basic_viewer)."
            << std::endl;
}

} // namespace CGAL

#endif // CGAL_USE_BASIC_VIEWER

#endif // DOXYGEN_RUNNING

#endif // CGAL_DRAW_SURFACE_VORONOI_DIAGRAM_H
