#!/bin/sh
# Checks that every example compiles (the manual includes them with \cgalExample), without
# building them: -DSVD_EXAMPLES_SYNTAX_ONLY=ON compiles each with -fsyntax-only (no object, no
# link). Clang when installed (the sanitizer job installs it; its -fsyntax-only takes about
# two thirds of GCC's time here), else the default compiler. scripts/check_examples.sh builds
# and runs them. ccache off: a syntax check writes no object to cache.
#   sh scripts/check_examples_syntax.sh [BUILD]      (BUILD defaults to build/examples_syntax)
set -e
cd "$(dirname "$0")/.."
build=${1:-build/examples_syntax}
if [ -z "$CXX" ] && command -v clang++ >/dev/null 2>&1; then
  CXX=clang++; export CXX
fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSVD_BUILD_PROGRAM=OFF -DSVD_BUILD_EXAMPLES=ON \
  -DSVD_EXAMPLES_SYNTAX_ONLY=ON -DSVD_USE_CCACHE=OFF >/dev/null
# with the program off, the default target is the examples' check alone (and draw_diagram's
# when CGAL's Qt5 is installed)
cmake --build "$build" -j2
echo "examples: all compile"
