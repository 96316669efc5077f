// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deprecated since 0.2, kept for one release: include <CGAL/draw_surface_voronoi_diagram.h>
// and call CGAL::draw(diagram), as for CGAL's other classes. This header only forwards there
// (where the deprecated CGAL::Surface_voronoi::draw() also lives) and warns at compile time,
// unless CGAL_NO_DEPRECATION_WARNINGS is defined; with CGAL_NO_DEPRECATED_CODE it is an error.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H

#define CGAL_DEPRECATED_HEADER "<CGAL/Surface_voronoi_diagram/draw.h>"
#define CGAL_REPLACEMENT_HEADER "<CGAL/draw_surface_voronoi_diagram.h>"
#include <CGAL/Installation/internal/deprecation_warning.h>

#include <CGAL/draw_surface_voronoi_diagram.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_DRAW_H
