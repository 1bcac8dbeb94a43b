#!/usr/bin/env bash
# Builds the Doxygen documentation of the PR_star_octree package (plain Debian `doxygen`, no CGAL
# documentation infrastructure needed).
#
#   scripts/build_docs.sh [--undocumented] [--check] [OUTPUT_DIR]      (default: build/doc)
#
# --undocumented also reports every undocumented public member (WARN_IF_UNDOCUMENTED = YES).
# --check        (the CTest test `doxygen_warnings`): prints the warnings and fails on any; exits
#                with 77 ("skipped") when doxygen is not installed.
#
# Configures doc/PR_star_octree/Doxyfile.in into OUTPUT_DIR/Doxyfile, runs doxygen, prints the
# number of warnings (the full list is in OUTPUT_DIR/doxygen_warnings.log) and where the HTML is.
# Exit code: doxygen's (warnings do not make it fail, except with --check).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
undocumented=NO
check=no
while [ $# -gt 0 ]; do
  case "$1" in
    --undocumented) undocumented=YES; shift ;;
    --check) check=yes; shift ;;
    -*) echo "build_docs.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
out="${1:-$root/build/doc}"

if ! command -v doxygen >/dev/null 2>&1; then
  echo "build_docs.sh: doxygen not found (Debian/Ubuntu: apt-get install -y doxygen)" >&2
  if [ "$check" = yes ]; then exit 77; fi
  exit 1
fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# '|' as the sed delimiter: the paths contain '/'.
case "$root$out" in *'|'*) echo "build_docs.sh: paths must not contain '|'" >&2; exit 1 ;; esac
sed -e "s|@PROJECT_SOURCE_DIR@|$root|g" \
    -e "s|@CMAKE_CURRENT_BINARY_DIR@|$out|g" \
    "$root/doc/PR_star_octree/Doxyfile.in" > "$out/Doxyfile"
echo "WARN_IF_UNDOCUMENTED   = $undocumented" >> "$out/Doxyfile"

rm -rf "$out/html"
(cd "$out" && doxygen Doxyfile)

log="$out/doxygen_warnings.log"
count=$( (grep -o 'warning:' "$log" || true) | wc -l)
echo "doxygen $(doxygen --version): $count warning(s); see $log"
echo "HTML: $out/html/index.html"
if [ "$check" = yes ] && [ "$count" -ne 0 ]; then
  cat "$log" >&2
  exit 1
fi
