#!/usr/bin/env bash
# Installs what the PR-star octree package needs on Debian 12 (run as root, or with sudo available).
# Skips apt entirely when everything is already there.
set -euo pipefail
# doxygen: for the test `doxygen_warnings` (zero warnings in the reference manual; about 2 s per run,
# skipped when doxygen is absent).
packages=(g++ make cmake libcgal-dev libboost-dev libeigen3-dev libtbb-dev libgmp-dev libmpfr-dev
          libtet1.5-dev zlib1g-dev liblz4-dev liblzma-dev doxygen
          python3-vtk9 python3-meshio gmsh xvfb)
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
