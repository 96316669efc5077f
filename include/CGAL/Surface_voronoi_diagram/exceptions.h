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
// The exceptions of the package. Invalid input that is cheap to detect throws
// `Input_error` (or a class derived from it) naming the element, in every build; what is
// costly to check stays a documented precondition (`validate_input()` checks it in every
// build). A failure that valid input can still meet throws `Numerical_error`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Base class of every exception thrown by the package.
class Error : public std::runtime_error
{
public:
  /// an error with the message `what`
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Invalid input, detected in every build; the message names the element concerned (a
/// vertex, face or site index, in the order of `vertices(tm)`, `faces(tm)` and the site
/// range): a face that is not a triangle, a non-finite or out-of-range coordinate, a
/// degenerate face, an isolated or non-manifold vertex, a site that is not on the mesh (a
/// descriptor of another mesh, a point that is not finite), a non-finite power weight or
/// embedding coordinate, a metric built on another mesh, an index out of range.
class Input_error : public Error
{
public:
  /// an error with the message `what`
  explicit Input_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A site given as a point is farther from the surface than the named parameter
/// `max_site_distance` allows.
class Site_too_far_error : public Input_error
{
public:
  /// site `site` is `distance` away from the surface
  Site_too_far_error(const std::string& what, std::size_t site, double distance)
    : Input_error(what), site(site), distance(distance)
  {}
  /// the index of the site
  std::size_t site;
  /// its distance from the surface
  double distance;
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A numerical computation failed although the input was valid (the eigen-solver did not
/// converge, a factorization failed, a metric returned a value that is not a number).
class Numerical_error : public Error
{
public:
  /// an error with the message `what`
  explicit Numerical_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// Two sites are at the same surface point (the same location once the sites given as
/// points are moved onto the surface), and the named parameter
/// `Surface_voronoi::parameters::coincident_sites` is `Coincident_sites::REJECT`, the default
/// (`Coincident_sites::MERGE` accepts them).
class Coincident_sites_error : public Input_error
{
public:
  /// sites `first` and `second` are at the same surface point
  Coincident_sites_error(const std::string& what, std::size_t first, std::size_t second)
    : Input_error(what), first(first), second(second)
  {}
  /// the lower index
  std::size_t first;
  /// the higher index
  std::size_t second;
};

} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_EXCEPTIONS_H
