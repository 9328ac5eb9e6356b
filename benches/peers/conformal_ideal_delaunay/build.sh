#!/usr/bin/env bash
# Build ConformalIdealDelaunay (geometryprocessing/ConformalIdealDelaunay, commit 901441c)
# in double precision, plus the benchmark driver cid_run.cpp, outside the penner tree.
#
#   benches/peers/conformal_ideal_delaunay/build.sh [BUILD_ROOT]   (default /work/peer-cid)
#
# Sources: bare git mirrors under $MIRROR/OWNER+NAME/repo (default /work/.mirror), one per
# repository, at these commits:
#   geometryprocessing/ConformalIdealDelaunay  901441cfc35d5ecdefc7b4c34218075f198d9669
#   libigl/libigl      (submodule ext/libigl)   3aefd187bd1a219ea4830aeb08122473b5c8ade9
#   gabime/spdlog      (submodule ext/spdlog)   a530b87fd0fcca818c4504f834340c5c263b3049
#   pybind/pybind11    (submodule ext/pybind11) 7516811315c76321e847cf28955937195c577d2f
# With network access, `git clone --recursive https://github.com/geometryprocessing/ConformalIdealDelaunay`
# gives the same tree (set MIRROR accordingly or adapt the extraction below).
# System packages (apt): cmake libeigen3-dev libboost-dev (g++ 12, Debian bookworm).
#
# Configuration: -DLIBIGL_WITH_CGAL=OFF (CGAL is how the peer gets MPFR: OFF means no
# WITH_MPFR, double only), -DRENDER_TEXTURE=OFF -DLIBIGL_WITH_EMBREE=OFF (rendering only;
# they would download GLFW/Embree), CMAKE_BUILD_TYPE=Release (the peer's CI setting; -O3
# -DNDEBUG with this cmake).
#
# Patches to the scratch copy (nothing else is changed):
#  1. eigen_from_system.cmake is injected with -DCMAKE_PROJECT_INCLUDE so that libigl's
#     cmake finds Eigen3::Eigen already defined and does not download Eigen (Eigen 3.4.0
#     from Debian instead of libigl's pinned 3.3.7).
#  2. Two lines appended to the peer's CMakeLists.txt: the executable cid_run (this
#     directory's cid_run.cpp, which only calls ConformalInterface.hh) linked to the peer's
#     own conformal_cpp library.
# Only the targets conformal_cpp and cid_run are built (the pybind11 module conformal_py
# and CSM_bin are not needed to time the double run).
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="${1:-/work/peer-cid}"
MIRROR="${MIRROR:-/work/.mirror}"
JOBS="${JOBS:-2}"
SRC="$ROOT/src"
BUILD="$ROOT/build"

if [ ! -f "$SRC/CMakeLists.txt" ]; then
  mkdir -p "$SRC"
  git --git-dir="$MIRROR/geometryprocessing+ConformalIdealDelaunay/repo" archive 901441cfc35d5ecdefc7b4c34218075f198d9669 | tar -x -C "$SRC"
  for sub in "libigl/libigl libigl 3aefd187bd1a219ea4830aeb08122473b5c8ade9" \
             "gabime/spdlog spdlog a530b87fd0fcca818c4504f834340c5c263b3049" \
             "pybind/pybind11 pybind11 7516811315c76321e847cf28955937195c577d2f"; do
    set -- $sub
    mkdir -p "$SRC/ext/$2"
    git --git-dir="$MIRROR/${1/\//+}/repo" archive "$3" | tar -x -C "$SRC/ext/$2"
  done
  # Patch 2: the benchmark driver.
  cat >> "$SRC/CMakeLists.txt" <<CMAKE

# penner benchmark driver (patch from penner benches/peers/conformal_ideal_delaunay/build.sh)
add_executable(cid_run "$HERE/cid_run.cpp")
target_link_libraries(cid_run PRIVATE conformal_cpp igl::core spdlog::spdlog)
target_include_directories(cid_run PRIVATE "$SRC/src/conformal_ideal_delaunay")
CMAKE
fi

cmake -S "$SRC" -B "$BUILD" \
  -DCMAKE_BUILD_TYPE=Release \
  -DLIBIGL_WITH_CGAL=OFF -DRENDER_TEXTURE=OFF -DLIBIGL_WITH_EMBREE=OFF \
  -DCMAKE_PROJECT_INCLUDE="$HERE/eigen_from_system.cmake" \
  -DPYTHON_EXECUTABLE="$(command -v python3)"
cmake --build "$BUILD" --target cid_run -j "$JOBS"
echo "built $BUILD/cid_run"
