// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of this package that CGAL 5.5 does not define. They chain with CGAL's
// own: `Surface_voronoi::parameters::input_face_map(m).face_patch_map(site_map)` (the
// package's parameter first, since CGAL's chain has no member for it).

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_PARAMETERS_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Surface_voronoi {
namespace internal_np {
enum input_face_map_t { input_face_map };
enum site_weight_map_t { site_weight_map };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A writable property map from faces of an output mesh to the faces of the diagram's
/// input mesh that contain them.
template <class Map>
CGAL::Named_function_parameters<Map, internal_np::input_face_map_t> input_face_map(const Map& m)
{
  return CGAL::Named_function_parameters<Map, internal_np::input_face_map_t>(m);
}

/// the same, appended to an existing chain of named parameters
template <class Map, class T, class Tag, class Base>
CGAL::Named_function_parameters<Map, internal_np::input_face_map_t, CGAL::Named_function_parameters<T, Tag, Base> >
input_face_map(const Map& m, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<Map, internal_np::input_face_map_t, CGAL::Named_function_parameters<T, Tag, Base> >(m, np);
}

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A readable property map from the sites, as the diagram's site range holds them
/// (`vertex_descriptor`, `Face_location` or `Point_3`), to their power weights (a type
/// convertible to `double`, in squared units of the metric). For vertex sites, a vertex
/// property map of the mesh. Weights by site index go in `Diagram_options::weights`.
template <class Map>
CGAL::Named_function_parameters<Map, internal_np::site_weight_map_t> site_weight_map(const Map& m)
{
  return CGAL::Named_function_parameters<Map, internal_np::site_weight_map_t>(m);
}

/// the same, appended to an existing chain of named parameters
template <class Map, class T, class Tag, class Base>
CGAL::Named_function_parameters<Map, internal_np::site_weight_map_t, CGAL::Named_function_parameters<T, Tag, Base> >
site_weight_map(const Map& m, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<Map, internal_np::site_weight_map_t, CGAL::Named_function_parameters<T, Tag, Base> >(m, np);
}

} // namespace parameters
} // namespace Surface_voronoi
} // namespace CGAL

#endif
