/*!
\ingroup PkgSurfaceVoronoiDiagramConcepts
\cgalConcept

A metric for `CGAL::Surface_voronoi_diagram`: the squared distance between a site and a
vertex of the mesh. The value may depend only on the site and the vertex (not on the face
it is asked for), which is what makes both sides of every edge agree. It may be computed
lazily: the diagram asks only for the vertices of faces the site propagates into.

Inside a face, the diagram interpolates the squared distances of the three corners
linearly (an approximation for metrics that are not embeddings, exact for
`SurfaceVoronoiEmbedding`).

\cgalRefines{CopyConstructible}
\cgalHasModel `CGAL::Biharmonic_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Euclidean_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Vertex_embedding`
\cgalHasModel `CGAL::Surface_voronoi::Geodesic_metric`
*/
class SurfaceVoronoiMetric
{
public:
  /// the mesh type
  typedef unspecified_type Triangle_mesh;
  /// `CGAL::Surface_voronoi::Lazy_metric_tag` for a lazy metric,
  /// `CGAL::Surface_voronoi::Embedding_tag` for a model of `SurfaceVoronoiEmbedding`
  typedef unspecified_type Metric_category;

  /// (lazy metrics) called once by the diagram with the sites, as face locations of `tm`
  void set_sites(const Triangle_mesh& tm,
                 const std::vector<CGAL::Polygon_mesh_processing::Face_location<Triangle_mesh, double> >& sites);

  /// (lazy metrics) the squared distance between site `i` and vertex `v`; finite and non-negative
  double squared_distance(std::size_t i, boost::graph_traits<Triangle_mesh>::vertex_descriptor v);
};
