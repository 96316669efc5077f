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
// Brackets around the package's deprecated declarations, which name each other: users of
// them are warned, the package's own headers are not.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DEPRECATION_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DEPRECATION_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#if defined(__GNUC__) || defined(__clang__)
#  define CGAL_SURFACE_VORONOI_DEPRECATED_BEGIN \
     _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wdeprecated-declarations\"")
#  define CGAL_SURFACE_VORONOI_DEPRECATED_END _Pragma("GCC diagnostic pop")
#else
#  define CGAL_SURFACE_VORONOI_DEPRECATED_BEGIN
#  define CGAL_SURFACE_VORONOI_DEPRECATED_END
#endif

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INTERNAL_DEPRECATION_H
