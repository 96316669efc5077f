/*!
\ingroup PkgSurfaceVoronoiDiagramConcepts
\cgalConcept

A metric of `CGAL::Surface_voronoi_diagram` given by per-vertex coordinates in
\f$ \mathbb{R}^d \f$. The embedding of a surface point is the barycentric interpolation of the
coordinates of its face's corners, and the squared distance between a site and a point is the
squared Euclidean distance of their embeddings. Inside a triangle the difference of two sites'
squared distances is then affine, so every bisector is a straight segment and the diagram of
the piecewise-linear embedding is computed exactly \cgalCite{cgal:xwx-svdm-22}.

The concept is a sibling of `SurfaceVoronoiLazyMetric`, not a refinement of it: a model gives
coordinates, never distances, and the diagram tells the two kinds apart by `Metric_category`.

<b>How the diagram uses a model.</b> The constructor of the diagram checks that
`triangle_mesh()` is the mesh it is given, then reads `dimension()` and the coordinates of
every vertex once, and never uses the model again: the model may be destroyed, or used by
other diagrams, afterwards. Only the `const` members below are called, so one model may serve
several diagrams in turn (as `Surface_voronoi::lloyd_relaxation()` does). A model that has a
member `bool is_cancelled() const` (as `CGAL::Biharmonic_embedding`) must not be cancelled
when a diagram is built with it (a precondition).

<b>Units.</b> Squared distances are in the squared units of the coordinates, and so are the
power weights of the sites (named parameter `Surface_voronoi::parameters::site_weight_map`):
squared lengths for `CGAL::Surface_voronoi::Euclidean_embedding`, the much smaller squared
biharmonic distances for `CGAL::Biharmonic_embedding`.
`Surface_voronoi::weight_for_length()` gives the weight for a length at a site, in these units.

\cgalHasModel `CGAL::Biharmonic_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Euclidean_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Vertex_embedding`

\sa `SurfaceVoronoiLazyMetric`
*/
class SurfaceVoronoiEmbedding
{
public:
  /// \name Types
  /// @{

  /// `CGAL::Surface_voronoi::Embedding_tag`: the diagram treats a metric as an embedding if
  /// and only if this type is `Embedding_tag`
  typedef CGAL::Surface_voronoi::Embedding_tag Metric_category;

  /// the type of the mesh, a model of `FaceListGraph` whose faces are triangles
  typedef unspecified_type Triangle_mesh;

  /// `boost::graph_traits<Triangle_mesh>::vertex_descriptor`
  typedef unspecified_type vertex_descriptor;

  /// @}

  /// \name Operations
  /// @{

  /// returns the mesh the embedding was built on. A diagram must be built on this very mesh
  /// (the same object, not a copy): its constructor throws `CGAL::Surface_voronoi::Input_error`
  /// otherwise.
  const Triangle_mesh& triangle_mesh() const;

  /// returns the dimension \f$ d \f$ of the embedding space.
  /// \pre The result is at least 1 when a diagram is built with the embedding.
  std::size_t dimension() const;

  /// writes the `dimension()` coordinates of vertex `v` of `triangle_mesh()` to `out`, as
  /// values convertible to `double`, and returns the iterator past the last one written.
  /// The diagram passes a `double*` (other callers, such as
  /// `Surface_voronoi::weight_for_length()`, an iterator of a `std::vector<double>`),
  /// so the member is a template on the output iterator.
  /// \pre The coordinates are finite numbers.
  template <class OutputIterator>
  OutputIterator coordinates(vertex_descriptor v, OutputIterator out) const;

  /// optional: the mesh as the model has prepared it (see
  /// `CGAL::Surface_voronoi::Prepared_mesh`), which a diagram built with this embedding then
  /// shares instead of preparing the mesh again.
  CGAL::Surface_voronoi::Prepared_mesh<Triangle_mesh> prepared_mesh() const;

  /// @}
};
