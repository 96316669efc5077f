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
// One problem found by `validate_input()`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_INPUT_PROBLEM_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_INPUT_PROBLEM_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// One thing `validate_input()` found wrong with the input of a diagram.
struct Input_problem
{
  /// what is wrong
  enum Kind
  {
    INVALID_MESH,         ///< the halfedge structure is not a valid polygon mesh
    EMPTY_MESH,           ///< the mesh has no face
    NOT_A_TRIANGLE,       ///< face `element` is not a triangle
    NON_FINITE_POINT,     ///< vertex `element` has a coordinate that is not a finite number
    ZERO_AREA_FACE,       ///< face `element` has no area, or too little to compute with: below 2^-44 (5.7e-14)
                          ///< times its squared longest edge (a needle or a cap whose height is below about
                          ///< 1.1e-13 of its longest edge), or a longest edge shorter than 2^-200 (6.2e-61)
    ISOLATED_VERTEX,      ///< vertex `element` belongs to no face
    NON_MANIFOLD_VERTEX,  ///< the faces around vertex `element` form several fans
    NO_SITES,             ///< the site range is empty
    SITE_NOT_ON_MESH,     ///< site `element` is not a vertex or a face location of the mesh, or not a finite point
    SITE_TOO_FAR,         ///< site `element`, a point, is farther from the surface than `max_site_distance`
    NON_FINITE_WEIGHT,    ///< the power weight of site `element` is not a finite number
    COINCIDENT_SITES,     ///< sites `element` and `other` are at the same surface point
    COORDINATE_OUT_OF_RANGE ///< vertex `element` has a coordinate beyond 2^200 (1.6e60) in magnitude, outside the
                            ///< documented coordinate range (squared areas would overflow): scale the mesh
  };
  /// what is wrong
  Kind kind;
  /// the index of the face, vertex (in the order of `faces(tm)`, `vertices(tm)`) or site concerned
  std::size_t element;
  /// the second site of `COINCIDENT_SITES` (0 otherwise)
  std::size_t other;
  /// one line saying what is wrong and where
  std::string message;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_INPUT_PROBLEM_H
