/*!
\ingroup PkgSurfaceVoronoiDiagramConcepts
\cgalConcept

A metric of `CGAL::Surface_voronoi_diagram` given by the squared distance between a site and
a vertex of the mesh, computed on demand: the diagram asks only for the corners of the faces
that a site's field propagates into, so a model may compute distances lazily (a fast-marching
front advanced only as far as it is asked, as `CGAL::Surface_voronoi::Geodesic_metric` does).
Inside a face the diagram interpolates the squared distances of the three corners linearly
\cgalCite{cgal:xwx-svdm-22} \cgalCite{cgal:bddvd}: exact for an embedding, an approximation
for any other metric.

The concept is a sibling of `SurfaceVoronoiEmbedding`, not a refinement of it; the diagram
tells the two kinds apart by `Metric_category`.

<b>One diagram at a time.</b> A lazy metric is used by one diagram at a time, during that
diagram's construction only. The constructor of the diagram checks that `triangle_mesh()` is
the mesh it is given, calls `set_sites()` once with all the sites, then calls
`squared_distance()` as often as it needs, and never uses the metric after its constructor
returns: the metric may then be queried, destroyed, or given to another diagram, whose
`set_sites()` starts it afresh. `set_sites()` must therefore drop whatever an earlier set of
sites left. The value for a site and a vertex must depend on them and on the set of sites
only, not on the order of the calls, so that diagrams are deterministic. The diagram only
compares the values of sites at one vertex (and their linear interpolations inside a face):
a model may add to all of them a term of the vertex alone, as
`CGAL::Surface_voronoi::Biharmonic_green_metric` does.

<b>Threads.</b> By default the diagram asks a lazy metric from one thread, even with
`CGAL::Parallel_tag`. A model whose `squared_distance()` may be called from several threads at
once, for different sites and for the same one, says so with the optional type
`Has_concurrent_squared_distance`, `CGAL::Tag_true` (as `CGAL::Surface_voronoi::Geodesic_metric`
does, with a lock per site): the diagram then propagates in blocks of faces, on every thread of
a `CGAL::Parallel_tag` diagram, and gives the same cells on any number of threads. The values
must still not depend on the order of the calls.

<b>Copies.</b> Copies must share no state: a copy is an independent metric that can serve
another diagram while the original serves one (read-only data such as the mesh may be
shared, the distances computed for a set of sites may not).

<b>Units.</b> Power weights (named parameter `Surface_voronoi::parameters::site_weight_map`)
are in the units of the squared distances the model returns.
`Surface_voronoi::weight_for_length()` measures these units around a site: it calls
`set_sites()` with the site and sites at vertices around it, and compares `squared_distance()`
between them, so a term of the vertex alone added to all sites' values does not count.

\cgalHasModel `CGAL::Surface_voronoi::Geodesic_metric`
\cgalHasModel `CGAL::Surface_voronoi::Biharmonic_green_metric`

\sa `SurfaceVoronoiEmbedding`
*/
class SurfaceVoronoiLazyMetric
{
public:
  /// \name Types
  /// @{

  /// `CGAL::Surface_voronoi::Lazy_metric_tag`
  typedef CGAL::Surface_voronoi::Lazy_metric_tag Metric_category;

  /// the type of the mesh, a model of `FaceListGraph` whose faces are triangles
  typedef unspecified_type Triangle_mesh;

  /// optional: `CGAL::Tag_true` if threads may call `squared_distance()` at once (see
  /// <b>Threads</b> above); without it, or with `CGAL::Tag_false`, one thread calls it
  typedef unspecified_type Has_concurrent_squared_distance;

  /// `boost::graph_traits<Triangle_mesh>::vertex_descriptor`
  typedef unspecified_type vertex_descriptor;

  /// @}

  /// \name Operations
  /// @{

  /// returns the mesh the metric was built on. A diagram must be built on this very mesh (the
  /// same object, not a copy): its constructor throws `CGAL::Surface_voronoi::Input_error`
  /// otherwise.
  const Triangle_mesh& triangle_mesh() const;

  /// starts from scratch with these sites, called once by the constructor of each diagram
  /// before any distance is asked. Site `i` is `sites[i]`: a face of `triangle_mesh()` and
  /// barycentric coordinates that are non-negative and sum to 1. With the named parameter
  /// `Surface_voronoi::parameters::coincident_sites` set to `MERGE`, two sites may be at the
  /// same point.
  void set_sites(const std::vector<CGAL::Polygon_mesh_processing::Face_location<Triangle_mesh, double> >& sites);

  /// returns the squared distance between site `i` and vertex `v` of `triangle_mesh()`. It
  /// may advance the metric's own state (hence not `const`).
  /// \pre `set_sites()` was called and `i` is less than the number of sites given to it.
  /// \post The result is finite and non-negative: the diagram throws
  ///       `CGAL::Surface_voronoi::Numerical_error` otherwise.
  double squared_distance(std::size_t i, vertex_descriptor v);

  /// @}

  /// \name Optional operations
  /// The package's own metrics have these; a model that has them gets the same savings.
  /// @{

  /// optional: returns `squared_distance(i, v)` for the `k`-th vertex `v` in the order of
  /// `vertices(triangle_mesh())`. The diagram asks by this index when the model offers it,
  /// without looking the vertex up.
  double indexed_squared_distance(std::size_t i, std::size_t k);

  /// optional: frees what the model keeps of the distances computed so far; a distance asked
  /// afterwards must be the same. A diagram calls it once its propagation is done, before it
  /// cuts the faces, when it asks for few distances more.
  void forget_distances();

  /// optional: the mesh as the model has prepared it (see
  /// `CGAL::Surface_voronoi::Prepared_mesh`), which a diagram built with this metric then
  /// shares instead of preparing the mesh again.
  CGAL::Surface_voronoi::Prepared_mesh<Triangle_mesh> prepared_mesh() const;

  /// @}
};
