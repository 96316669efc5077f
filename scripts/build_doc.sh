#!/bin/sh
# Builds the manual with doxygen and fails on any warning. The doc target first renders the
# figures (target svd_figures, a Release build of doc/Surface_voronoi_diagram/figures/make_figures.cpp);
# the README's picture is then refreshed from them (the renderer is deterministic, so an
# unchanged renderer leaves it unchanged).
set -e
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null 2>&1 || { apt-get install -y -qq --no-install-recommends doxygen >/dev/null; }
cmake -S . -B build/doc -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/doc -j2 --target doc
if [ -s build/doc/doc/warnings.log ]; then
  echo "doxygen warnings:"; cat build/doc/doc/warnings.log; exit 1
fi
mkdir -p doc/Surface_voronoi_diagram/fig
cp build/doc/doc_figures/svd_lampshade.png doc/Surface_voronoi_diagram/fig/lampshade_voronoi.png
echo "manual: build/doc/doc/html/index.html (no warnings); figures: build/doc/doc_figures"
