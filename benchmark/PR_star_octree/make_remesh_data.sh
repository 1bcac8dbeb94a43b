#!/usr/bin/env bash
# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# The three meshes of the remeshing benchmark (bench_simplification --side-by-side, issue 22,
# results/remeshing.md), made from Debian packages alone; they are never committed.
#
#   fandisk_tetgen.1.node/.ele  TetGen (`tetgen` package) on CGAL's fandisk.off (libcgal-demo's
#                               data.tar.gz): `tetgen -pqQ -a2.5e-7`, about 217K vertices / 1.18M
#                               tetrahedra, one region, sharp features, genus 0
#   complex_mesh3.mesh          CGAL Mesh_3 (libcgal-dev) on the polyhedral complex of the same data set
#                               (meshes/patch-*.off: a cube cut into three subdomains), features
#                               protected, cell size 2.2: about 72K vertices / 407K tetrahedra, labels 1-3
#                               (make_mesh3_complex.cpp, compiled here with g++)
#   inclusions_gmsh.msh         gmsh (OpenCASCADE) on a 2 x 1 x 1 box with a spherical and a cylindrical
#                               inclusion (BooleanFragments: conforming interfaces), physical volumes
#                               matrix 1, sphere 2, cylinder 3, size 0.0302: about 62K vertices / 350K
#                               tetrahedra
#
# usage: make_remesh_data.sh [OUT_DIR]   (default: ./remesh_data)
# Needs: tetgen gmsh libcgal-demo libcgal-dev libgmp-dev libmpfr-dev g++ (apt-get install ...).
# Takes about a minute (the Mesh_3 program compiles in about 50 s, each mesher runs 7-14 s).

set -euo pipefail

out=${1:-remesh_data}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
data_tar=/usr/share/doc/libcgal-demo/data.tar.gz

missing=()
command -v tetgen >/dev/null || missing+=(tetgen)
command -v gmsh >/dev/null || missing+=(gmsh)
command -v g++ >/dev/null || missing+=(g++)
[[ -f $data_tar ]] || missing+=(libcgal-demo)
[[ -f /usr/include/CGAL/make_mesh_3.h ]] || missing+=(libcgal-dev)
if ((${#missing[@]})); then
  echo "make_remesh_data.sh: missing: ${missing[*]} (apt-get install ${missing[*]})" >&2
  exit 1
fi

mkdir -p "$out"
cd "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# CGAL's data set: the fandisk and the six patches of the polyhedral complex.
tar -xzf "$data_tar" -C "$work" data/meshes/fandisk.off \
  data/meshes/patch-01.off data/meshes/patch-13.off data/meshes/patch-20.off \
  data/meshes/patch-21.off data/meshes/patch-23.off data/meshes/patch-30.off

echo "== TetGen fandisk"
cp "$work/data/meshes/fandisk.off" fandisk_tetgen.off
# -p: a piecewise-linear complex (the closed surface), -q: quality (radius-edge 2), -a: volume bound,
# -Q: quiet.  Writes fandisk_tetgen.1.node/.ele/.face/.edge (the last two are not needed).
tetgen -pqQ -a2.5e-7 fandisk_tetgen.off
rm -f fandisk_tetgen.1.face fandisk_tetgen.1.edge fandisk_tetgen.1.smesh fandisk_tetgen.off
echo "fandisk_tetgen.1.node: $(head -1 fandisk_tetgen.1.node | awk '{print $1}') vertices," \
  "$(head -1 fandisk_tetgen.1.ele | awk '{print $1}') tetrahedra"

echo "== CGAL Mesh_3 polyhedral complex"
g++ -O2 -std=c++17 -DNDEBUG -frounding-math "$here/make_mesh3_complex.cpp" -o "$work/make_mesh3_complex" \
  -lgmp -lmpfr
"$work/make_mesh3_complex" "$work/data" 2.2 complex_mesh3.mesh

echo "== gmsh box with two inclusions"
cat >"$work/inclusions.geo" <<'EOF'
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Sphere(2) = {0.5, 0.5, 0.5, 0.3};
Cylinder(3) = {1.5, 0.5, 0.2, 0, 0, 0.6, 0.2};
// One conforming mesh of the three volumes: the inclusions cut out of the box, their surfaces shared.
BooleanFragments{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; }
sphere() = Volume In BoundingBox{0.19, 0.19, 0.19, 0.81, 0.81, 0.81};
cylinder() = Volume In BoundingBox{1.29, 0.29, 0.19, 1.71, 0.71, 0.81};
matrix() = Volume{:};
matrix() -= {sphere(), cylinder()};
Physical Volume("matrix", 1) = {matrix()};
Physical Volume("sphere", 2) = {sphere()};
Physical Volume("cylinder", 3) = {cylinder()};
Mesh.MeshSizeMax = 0.0302;
EOF
# One thread: the same mesh on every run.  Only the physical volumes are written (tetrahedra).
gmsh -3 -nt 1 -v 2 "$work/inclusions.geo" -o inclusions_gmsh.msh
echo "inclusions_gmsh.msh: $(awk '/^\$Nodes/{getline; print $2; exit}' inclusions_gmsh.msh) vertices," \
  "$(awk '/^\$Elements/{getline; print $2; exit}' inclusions_gmsh.msh) tetrahedra"

ls -l "$PWD"
