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
// A mesh prepared once for the package's functions and classes, which share it through the
// named parameter `prepared_mesh`.

#ifndef CGAL_SURFACE_VORONOI_DIAGRAM_PREPARED_MESH_H
#define CGAL_SURFACE_VORONOI_DIAGRAM_PREPARED_MESH_H

#include <CGAL/license/Surface_voronoi_diagram.h>

#include <CGAL/Surface_voronoi_diagram/parameters.h>
#include <CGAL/Surface_voronoi_diagram/internal/Indexed_mesh.h>
#include <CGAL/Surface_voronoi_diagram/internal/parallel.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <memory>

namespace CGAL {
namespace Surface_voronoi {

/// \ingroup PkgSurfaceVoronoiDiagramRef
/// A triangle mesh prepared for the package: its elements numbered, its points copied in
/// `double`, its adjacency and connected components indexed, and the checks of the input made
/// on it remembered. `validate_input()`, the metrics (`CGAL::Biharmonic_embedding`,
/// `Biharmonic_green_metric`, `Geodesic_metric`), `CGAL::Surface_voronoi_diagram` and
/// `lloyd_relaxation()` each prepare the mesh they are given; given this object with the named
/// parameter `Surface_voronoi::parameters::prepared_mesh`, they share it instead, and the
/// checks made by one are not made again by the next. A call given the prepared mesh of
/// another mesh, or of other points, prepares its own (it compares them). Copies share the
/// preparation, which the metrics and diagrams given it hold as long as they live.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: whether the preparation runs on every core (where
///         the mesh numbers its elements itself, a `Surface_mesh` without removed elements);
///         the result is the same either way
template <class TriangleMesh, class ConcurrencyTag = CGAL::Sequential_tag>
class Prepared_mesh
{
public:
  /// Prepares `tm`, which must stay alive and unchanged while the prepared mesh is used.
  ///
  /// \param tm the mesh
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`; the
  ///       calls given the prepared mesh must use the same points}
  ///     \cgalParamType{a model of `ReadablePropertyMap`}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Surface_voronoi::parameters::checked_mesh_topology}
  ///     \cgalParamDescription{`true` if the caller has checked that `tm` is a valid polygon mesh
  ///       of triangles whose vertices are manifold (as a reader that builds the mesh from a
  ///       polygon soup it checked does): `validate_input()` and the diagram given this
  ///       prepared mesh then skip these checks, and check the geometry only}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \pre `tm` is a valid polygon mesh with at least one face
  /// \throws Input_error if a face of `tm` is not a triangle
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Prepared_mesh(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_mesh(std::make_shared<const internal::Indexed_mesh<TriangleMesh> >(tm,
          CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                             get_const_property_map(CGAL::vertex_point, tm)),
          internal::use_threads<ConcurrencyTag>())),
      m_topology_checked(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::checked_mesh_topology), false))
  {}

  /// the mesh prepared
  const TriangleMesh& triangle_mesh() const { return *m_mesh->source_mesh; }

  /// \cond SKIP_IN_MANUAL
  Prepared_mesh() {}
  explicit Prepared_mesh(const std::shared_ptr<const internal::Indexed_mesh<TriangleMesh> >& mesh) : m_mesh(mesh) {}
  const std::shared_ptr<const internal::Indexed_mesh<TriangleMesh> >& indexed_mesh() const { return m_mesh; }
  bool topology_checked() const { return m_topology_checked; }
  /// \endcond

private:
  std::shared_ptr<const internal::Indexed_mesh<TriangleMesh> > m_mesh;
  bool m_topology_checked = false;
};

namespace internal {

/// the named parameter `prepared_mesh` of `np`, or an empty prepared mesh
template <class TriangleMesh, class NamedParameters>
auto prepared_mesh_of(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::prepared_mesh), Prepared_mesh<TriangleMesh>());
}

} // namespace internal
} // namespace Surface_voronoi
} // namespace CGAL

#endif // CGAL_SURFACE_VORONOI_DIAGRAM_PREPARED_MESH_H
