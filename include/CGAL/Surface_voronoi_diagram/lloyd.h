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
// Deprecated: renamed lloyd_relaxation.h; this header keeps the old name for one release.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_H

#include <CGAL/Surface_voronoi_diagram/lloyd_relaxation.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_LLOYD_H
