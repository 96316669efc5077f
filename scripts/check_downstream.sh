#!/bin/sh
# Installs the package into a prefix under build/downstream, then configures, builds and runs
# the downstream project test/Surface_voronoi_diagram/downstream (its programs are the README's
# C++ blocks) against it, in two configurations:
#   with  - TBB and METIS found (both required here: the CI installs them);
#   without - the package configured with -DSVD_USE_TBB=OFF -DSVD_USE_METIS=OFF; the downstream
#             project is then configured with TBB unfindable, and its programs must link
#             neither TBB nor METIS.
#   sh scripts/check_downstream.sh [with|without]...   (default: both)
set -e
cd "$(dirname "$0")/.."
root="$(pwd)"
configs=${*:-with without}
for config in $configs; do
  echo "== downstream: $config TBB and METIS"
  dir="$root/build/downstream/$config"
  case $config in
    with) options="-DSVD_USE_TBB=ON -DSVD_USE_METIS=ON"; downstream_options="" ;;
    without) options="-DSVD_USE_TBB=OFF -DSVD_USE_METIS=OFF"; downstream_options="-DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON" ;;
    *) echo "check_downstream.sh: unknown configuration $config (with or without)"; exit 2 ;;
  esac
  rm -rf "$dir/prefix"
  cmake -S . -B "$dir/package" -DSVD_BUILD_PROGRAM=OFF $options >/dev/null
  cmake --install "$dir/package" --prefix "$dir/prefix" >/dev/null
  targets=$(find "$dir/prefix" -name Surface_voronoi_diagramTargets.cmake)
  [ -n "$targets" ] || { echo "no Surface_voronoi_diagramTargets.cmake installed"; exit 1; }
  if [ $config = with ]; then
    for needed in CGAL::TBB_support SVD::METIS; do
      grep -q "$needed" "$targets" || { echo "the installed target does not link $needed (is it installed?)"; exit 1; }
    done
  elif grep -Eq "TBB|METIS" "$targets"; then
    echo "the installed target still names TBB or METIS:"; grep -E "TBB|METIS" "$targets"; exit 1
  fi
  # without, CMAKE_DISABLE_FIND_PACKAGE_TBB goes unused (nothing looks for TBB): no warning for it
  cmake --no-warn-unused-cli -S test/Surface_voronoi_diagram/downstream -B "$dir/app" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$dir/prefix" -DSVD_SOURCE_DIR="$root" $downstream_options >/dev/null
  cmake --build "$dir/app" -j2
  if [ $config = without ]; then
    for program in "$dir"/app/readme_*; do
      [ -x "$program" ] || continue   # (the extracted sources are there too)
      if ldd "$program" | grep -Ei "tbb|metis"; then echo "$program links TBB or METIS"; exit 1; fi
    done
  fi
  (cd "$dir/app" && ctest --output-on-failure)
done
echo "downstream: the README's programs build and run against the installed package ($configs)"
