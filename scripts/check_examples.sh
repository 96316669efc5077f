#!/bin/sh
# Builds the examples (-DSVD_BUILD_EXAMPLES=ON) and runs each one on its default input in
# BUILD/run; fails if a program exits non-zero or does not write its output.
#   sh scripts/check_examples.sh [BUILD]      (BUILD defaults to build/examples)
set -e
cd "$(dirname "$0")/.."
build=${1:-build/examples}
cmake -S . -B "$build" -DSVD_BUILD_EXAMPLES=ON >/dev/null
cmake --build "$build" -j2
bin="$(pwd)/$build/examples/Surface_voronoi_diagram"
rm -rf "$build/run" && mkdir -p "$build/run" && cd "$build/run"
cp -r "$bin/data" .
run() {   # run PROGRAM [ARGS...] -- OUTPUT...
  program=$1; shift
  args=""; while [ "$1" != "--" ]; do args="$args $1"; shift; done; shift
  echo "== $program$args"
  "$bin/$program" $args
  for f in "$@"; do [ -s "$f" ] || { echo "$program did not write $f"; exit 1; }; done
}
run quick_start --
run power_diagram -- power_diagram.ply
run breaklines -- breaklines.ply
run lloyd_relaxation -- lloyd_before.ply lloyd_after.ply
run blue_noise_sites -- random_sites.ply blue_noise_sites.ply
run compare_metrics -- compare_biharmonic.ply compare_euclidean.ply compare_geodesic.ply compare_rvd.ply
run remeshing data/lampshade_thin.off 2000 10 remeshed.off -- remeshed.off
run geodesic_remeshing data/lampshade_thin.off 500 5 geodesic_remeshed.off -- geodesic_remeshed.off
run feature_remeshing data/lampshade_thin.off 2000 60 feature_remeshed.off -- feature_remeshed.off
run graph_algorithms --
run polyhedron_diagram --
run user_metric --
run vertex_point_map --
run voronoi_polygon_mesh -- voronoi_cells.off
run bisector_polylines -- bisectors.polylines.txt
run site_maps -- site_maps.ply
run validate_input --
run progress_callback --
run parallel_diagram data/lampshade_thin.off 2 --
run epeck_kernel --
run own_relaxation --
run prescribed_areas --
if [ -x "$bin/biharmonic_cholmod" ]; then run biharmonic_cholmod --; fi
echo "all examples ran; outputs in $build/run"
