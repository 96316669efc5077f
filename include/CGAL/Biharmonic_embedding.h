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
// Forwarding header: CGAL::Biharmonic_embedding, the biharmonic embedding of a triangle
// mesh, the default metric of CGAL::Surface_voronoi_diagram.

#ifndef CGAL_BIHARMONIC_EMBEDDING_H
#define CGAL_BIHARMONIC_EMBEDDING_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/Biharmonic_embedding.h>

#endif // CGAL_BIHARMONIC_EMBEDDING_H
