/*!
\ingroup PkgSurfaceVoronoiDiagramConcepts
\cgalConcept

A `SurfaceVoronoiMetric` given by per-vertex coordinates in \f$ \mathbb{R}^d \f$. The
embedding of a surface point is the barycentric interpolation of its face's corners, the
squared distance between a site and a point is the squared Euclidean distance of their
embeddings, and per-face cutting is exact: inside a triangle the difference of two sites'
squared distances is affine, so every bisector is a straight segment.

\cgalRefines{SurfaceVoronoiMetric}
\cgalHasModel `CGAL::Biharmonic_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Euclidean_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Vertex_embedding`
*/
class SurfaceVoronoiEmbedding
{
public:
  /// `CGAL::Surface_voronoi::Embedding_tag`
  typedef unspecified_type Metric_category;

  /// the dimension `d` of the embedding
  std::size_t dimension() const;

  /// writes the `dimension()` coordinates of `v` to `out`
  void coordinates(boost::graph_traits<Triangle_mesh>::vertex_descriptor v, double* out) const;
};
