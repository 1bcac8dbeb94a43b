#!/usr/bin/env bash
# Builds the Doxygen documentation of the PR_star_octree package (plain Debian `doxygen`, no CGAL
# documentation infrastructure needed).
#
#   scripts/build_docs.sh [--undocumented] [OUTPUT_DIR]      (default: build/doc)
#
# --undocumented also reports every undocumented public member (WARN_IF_UNDOCUMENTED = YES).
#
# Configures doc/PR_star_octree/Doxyfile.in into OUTPUT_DIR/Doxyfile, runs doxygen, prints the
# number of warnings (the full list is in OUTPUT_DIR/doxygen_warnings.log) and where the HTML is.
# Exit code: doxygen's (warnings do not make it fail).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
undocumented=NO
if [ "${1:-}" = "--undocumented" ]; then
  undocumented=YES
  shift
fi
out="${1:-$root/build/doc}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"

if ! command -v doxygen >/dev/null 2>&1; then
  echo "build_docs.sh: doxygen not found (Debian/Ubuntu: apt-get install -y doxygen)" >&2
  exit 1
fi

# '|' as the sed delimiter: the paths contain '/'.
case "$root$out" in *'|'*) echo "build_docs.sh: paths must not contain '|'" >&2; exit 1 ;; esac
sed -e "s|@PROJECT_SOURCE_DIR@|$root|g" \
    -e "s|@CMAKE_CURRENT_BINARY_DIR@|$out|g" \
    "$root/doc/PR_star_octree/Doxyfile.in" > "$out/Doxyfile"
echo "WARN_IF_UNDOCUMENTED   = $undocumented" >> "$out/Doxyfile"

rm -rf "$out/html"
(cd "$out" && doxygen Doxyfile)

log="$out/doxygen_warnings.log"
count=$(grep -o 'warning:' "$log" | wc -l)
echo "doxygen $(doxygen --version): $count warning(s); see $log"
echo "HTML: $out/html/index.html"
