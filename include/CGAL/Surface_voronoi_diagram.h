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
// Forwarding header of the Surface_voronoi_diagram package: the diagram class, its default
// metric, its named parameters, the outputs of the cells (the arrangement, the cells as a
// polygon mesh, the bisector polylines and Voronoi vertices, the site maps of the input),
// and input: validation, and the location of points near the surface. The other metrics, sampling, Lloyd relaxation, site insertion,
// refinement and the dual have headers of their own in CGAL/Surface_voronoi_diagram/.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>
#include <CGAL/Surface_voronoi_diagram/Surface_voronoi_diagram.h>
#include <CGAL/Surface_voronoi_diagram/arrangement.h>
#include <CGAL/Surface_voronoi_diagram/bisector_polylines.h>
#include <CGAL/Surface_voronoi_diagram/locate_points.h>
#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/power_weights.h>
#include <CGAL/Surface_voronoi_diagram/site_maps.h>
#include <CGAL/Surface_voronoi_diagram/validate_input.h>
#include <CGAL/Surface_voronoi_diagram/voronoi_polygon_mesh.h>

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_H
