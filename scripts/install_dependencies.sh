#!/usr/bin/env bash
# Installs what the PR-star octree package needs on Debian 12 (run as root, or with sudo available).
# Skips apt entirely when everything is already there.
#
#   scripts/install_dependencies.sh               everything: building, and running every test
#   scripts/install_dependencies.sh --build-only  what building needs (the library's users, prstar,
#                                                 the tests, examples and benchmarks): what
#                                                 scripts/setup.sh installs
#   scripts/install_dependencies.sh --python      what building needs, plus the Python module's
#                                                 (pybind11, the Python headers, numpy)
#   scripts/install_dependencies.sh --paraview    what building needs, plus ParaView 5.11 and its
#                                                 development files (the ParaView plugin)
#   scripts/install_dependencies.sh --benchmarks  what building needs, plus what the remeshing
#                                                 benchmark's data and picture need (TetGen, gmsh,
#                                                 CGAL's data set, matplotlib; see
#                                                 benchmark/PR_star_octree/make_remesh_data.sh)
set -euo pipefail
# Building: the compiler, CMake, CGAL and its dependencies, Eigen (distortion), TBB (parallel
# leaves), TetGen (prstar generate --tetgen), zlib, lz4, lzma (compressed VTU).
build=(g++ make cmake libcgal-dev libboost-dev libeigen3-dev libtbb-dev libgmp-dev libmpfr-dev
       libtet1.5-dev zlib1g-dev liblz4-dev liblzma-dev)
# Testing only (each test that needs one is skipped without it): doxygen for `doxygen_warnings`
# (zero warnings in the reference manual); VTK's and meshio's Python bindings and gmsh for the
# format interoperability tests; xvfb to render the pictures (scripts/make_pictures.sh) off screen;
# Open MPI for the distributed octree (optional: without it the MPI tool commands, tests and
# example are not built); HDF5 for the XDMF heavy data (optional: without it only inline-XML .xdmf
# files are read and written) and h5py for meshio's XDMF files (interop_xdmf.py); pybind11, the
# Python headers, numpy, pytest and mypy for the Python module and its tests (optional: without them the
# module is not built; scripts/install_python.sh installs the module alone); ParaView, its development
# files and the two development packages its CMake configuration needs without declaring them, for
# the ParaView plugin and its pvpython/pvbatch tests (optional: without them the plugin is not
# built).  python3-paraview conflicts with python3-vtk9: both install the Python module vtkmodules
# (ParaView's is VTK 9.2, python3-vtk9's VTK 9.1), so the whole list takes VTK's Python bindings
# from ParaView (python3-vtk9 alone serves the tests that need VTK, not ParaView; apt replaces it
# by python3-paraview when this script installs the whole list on a machine that has it).
paraview=(paraview paraview-dev python3-paraview libutfcpp-dev libdouble-conversion-dev python3-mpi4py)
test_only=(doxygen python3-meshio gmsh xvfb libopenmpi-dev openmpi-bin libhdf5-dev python3-h5py
           pybind11-dev python3-dev python3-numpy python3-pytest mypy "${paraview[@]}")
case "${1:-}" in
  --build-only) packages=("${build[@]}") ;;
  --python) packages=("${build[@]}" pybind11-dev python3-dev python3-numpy) ;;
  --paraview) packages=("${build[@]}" "${paraview[@]}" xvfb) ;;
  --benchmarks) packages=("${build[@]}" tetgen gmsh libcgal-demo python3-matplotlib) ;;
  "") packages=("${build[@]}" "${test_only[@]}") ;;
  *) echo "install_dependencies.sh: unknown option $1 (--build-only, --python, --paraview, --benchmarks, or nothing for everything)" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "installing: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
