#!/bin/sh
# Builds the manual with doxygen and fails on any warning.
set -e
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null 2>&1 || { apt-get install -y -qq --no-install-recommends doxygen >/dev/null; }
cmake -S . -B build/doc >/dev/null
mkdir -p build/doc/doc   # doxygen opens its warnings log before it creates the output folder
cmake --build build/doc --target doc
if [ -s build/doc/doc/warnings.log ]; then
  echo "doxygen warnings:"; cat build/doc/doc/warnings.log; exit 1
fi
echo "manual: build/doc/doc/html/index.html (no warnings)"
