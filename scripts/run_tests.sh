#!/bin/sh
# Builds and runs the whole test suite (the README's second command calls this).
set -e
cd "$(dirname "$0")/.."
sh scripts/install_dependencies.sh
cmake -S . -B build/tests -DCMAKE_BUILD_TYPE=Release -DSVD_BUILD_TESTS=ON >/dev/null
cmake --build build/tests -j2
cd build/tests && ctest --output-on-failure -j2
