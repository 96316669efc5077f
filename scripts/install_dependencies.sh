#!/bin/sh
# Installs, from Debian 12's packages, what the package needs and what is missing.
# Required: the five of the design card, and python3 for the regression matrix. Optional
# (detected at configure time): CGAL's data set, TBB, METIS, ccache, doxygen, and
# CHOLMOD + OpenBLAS (the program's embedding factorization, the biharmonic_cholmod example
# and its test, the benchmark's third factorization).
set -e
required="cmake g++ make python3 libcgal-dev libeigen3-dev libspectra-dev libboost-graph-dev catch2"
optional="ccache libcgal-demo libtbb-dev libmetis-dev libsuitesparse-dev libopenblas0-pthread doxygen"
missing=""
for p in $required $optional; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "installing:$missing"
  $SUDO apt-get update -qq
  # --no-install-recommends: libcgal-demo would otherwise pull in Qt.
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $required >/dev/null
  for p in $optional; do
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$p" >/dev/null 2>&1 \
      || echo "optional package $p not installed (continuing)"
  done
fi
