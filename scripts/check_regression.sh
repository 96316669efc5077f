#!/bin/sh
# Runs the regression matrix (test/Surface_voronoi_diagram/regression/run_matrix.py) with a
# Release build of the surface_voronoi program: every recorded program run must give the same
# cells, counts and areas (within the tolerances run_matrix.py states). Real-model entries run
# only when ../shared/data/meshes exists.
#   sh scripts/check_regression.sh [BUILD] [run_matrix.py options...]   (BUILD: build/release)
set -e
cd "$(dirname "$0")/.."
build=${1:-build/release}
[ $# -gt 0 ] && shift
command -v python3 >/dev/null 2>&1 || { apt-get install -y -qq --no-install-recommends python3 >/dev/null; }
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target surface_voronoi
python3 test/Surface_voronoi_diagram/regression/run_matrix.py "$build/surface_voronoi" "$@"
