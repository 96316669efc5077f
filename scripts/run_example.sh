#!/bin/sh
# Builds the surface_voronoi program and runs the main job on a bundled thin-walled shell:
# a biharmonic Voronoi diagram of 200 random sites, written as a coloured PLY.
set -e
cd "$(dirname "$0")/.."
sh scripts/install_dependencies.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j2 --target surface_voronoi
./build/release/surface_voronoi examples/Surface_voronoi_diagram/data/lampshade_thin.off \
  --random 200 --seed 1 --output lampshade_voronoi.ply --sites-out lampshade_sites.xyz --stats
echo "wrote lampshade_voronoi.ply (open it in MeshLab or ParaView) and lampshade_sites.xyz"
