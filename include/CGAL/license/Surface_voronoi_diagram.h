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
// The license check every public header of the package includes first, in the form of
// CGAL's own CGAL/license/<Package>.h files: the package is GPL-3.0-or-later unless
// CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE names a commercial license date.

#ifndef CGAL_LICENSE_SURFACE_VORONOI_DIAGRAM_H
#define CGAL_LICENSE_SURFACE_VORONOI_DIAGRAM_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE

#  if CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE
#    if defined(CGAL_LICENSE_WARNING)
       CGAL_pragma_warning("Your commercial license for CGAL does not cover "
                           "this release of the Surface Voronoi Diagrams package.")
#    endif
#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
of the Surface Voronoi Diagrams package. \
You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif
#  endif

#else // no CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE is not defined."
                          "\nYou use the Surface Voronoi Diagrams package under "
                          "the terms of the GPLv3+.")
#  endif
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE is not defined.\
 You use the Surface Voronoi Diagrams package under the terms of \
the GPLv3+. You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif

#endif // no CGAL_SURFACE_VORONOI_DIAGRAM_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_SURFACE_VORONOI_DIAGRAM_H
