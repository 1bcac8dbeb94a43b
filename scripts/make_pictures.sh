#!/usr/bin/env bash
# Remakes the pictures of the manual and the README (doc/PR_star_octree/fig/*.png) from the tool's
# own output files, rendered by scripts/render_pictures.py with VTK's Python bindings off screen.
#
#   bash scripts/make_pictures.sh [OUT_DIR]          (default: doc/PR_star_octree/fig)
#
# Meshes: the real meshes of ../shared/data when present (bunny_sofa.vtu for the octree, the SPX
# volume-rendering dataset spx_zsweep.off and its scalar field for the boundary classes and the
# distortion, skull_14k.off and its CT intensity for the critical points and the Morse complexes),
# otherwise meshes made by `prstar generate` (CGAL Mesh_3; for the topology, a ball with a noisy sum
# of bumps written by render_pictures.py --noisy-field).  Needs a built prstar (scripts/build.sh, or
# the one named by the environment variable PRSTAR), python3-vtk9 and, on a machine without a
# display, xvfb-run (both installed by scripts/install_dependencies.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/doc/PR_star_octree/fig}"
prstar="${PRSTAR:-$root/build/tools/prstar/prstar}"
[ -x "$prstar" ] || { echo "make_pictures.sh: build prstar first (bash scripts/build.sh)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

shared="$root/../shared/data"
if [ -f "$shared/bunny_sofa.vtu" ] && [ -f "$shared/spx_zsweep.off" ]; then
  octree_mesh="$shared/bunny_sofa.vtu"; octree_name="bunny (SOFA)"
  field_mesh="$shared/spx_zsweep.off"; field_name="SPX (EDF)"
else
  "$prstar" generate --shape torus --cell-size 0.08 -o "$work/torus.mesh" --quiet
  "$prstar" generate --shape sphere --cell-size 0.08 -o "$work/sphere.mesh" --quiet
  octree_mesh="$work/torus.mesh"; octree_name="torus (Mesh_3)"
  field_mesh="$work/sphere.mesh"; field_name="ball (Mesh_3, field x)"
fi
if [ -f "$shared/skull_14k.off" ]; then
  topology_mesh="$shared/skull_14k.off"; topology_field=scalar; topology_name="skull (CT intensity)"
else
  "$prstar" generate --shape sphere --cell-size 0.07 -o "$work/ball.vtu" --quiet
  /usr/bin/python3 "$root/scripts/render_pictures.py" --noisy-field "$work/ball.vtu" "$work/ball_f.vtu" > /dev/null
  topology_mesh="$work/ball_f.vtu"; topology_field=f; topology_name="ball (Mesh_3, noisy bumps)"
fi
printf '%s\n%s\n%s\n' "$octree_name" "$field_name" "$topology_name" > "$work/names.txt"

"$prstar" boundary "$octree_mesh" -o "$work/mesh_boundary.vtu" --quiet > /dev/null
"$prstar" boundary "$field_mesh" -o "$work/field_boundary.vtu" --quiet > /dev/null
"$prstar" stats "$octree_mesh" --kv 20 --octree "$work/octree_kv20.vtu" --quiet > /dev/null
"$prstar" stats "$octree_mesh" --kv 200 --octree "$work/octree_kv200.vtu" --quiet > /dev/null
if [ "$field_mesh" = "$work/sphere.mesh" ]; then
  "$prstar" curvature "$field_mesh" --field x -o "$work/curvature.vtu" --quiet > /dev/null
else
  "$prstar" curvature "$field_mesh" -o "$work/curvature.vtu" --quiet > /dev/null
fi
"$prstar" critical "$topology_mesh" --field "$topology_field" --csv "$work/critical.csv" --quiet > /dev/null
"$prstar" morse "$topology_mesh" --field "$topology_field" --persistence 5% -o "$work/morse.vtu" \
  --arcs "$work/morse_arcs.vtp" --csv "$work/morse_pairs.csv" --json > "$work/morse.json"

render=(/usr/bin/python3 "$root/scripts/render_pictures.py" "$work" "$out")
offscreen=()
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run > /dev/null; then
  offscreen=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
"${offscreen[@]}" "${render[@]}"

# The Python example's picture (the module from PRSTAR_PYTHON, default build/python, when built):
# the distortion of the height on the boundary of the octree's mesh.
python_dir="${PRSTAR_PYTHON:-$root/build/python}"
if [ -f "$python_dir/prstar/__init__.py" ]; then
  PYTHONPATH="$python_dir" "${offscreen[@]}" /usr/bin/python3 \
    "$root/examples/PR_star_octree/python/boundary_and_curvature.py" "$octree_mesh" z -o "$out/python_distortion.png"
else
  echo "make_pictures.sh: no Python module in $python_dir (PRSTAR_PYTHON): python_distortion.png not remade" >&2
fi
