#!/usr/bin/env bash
# Builds the Python module `prstar` and installs it into Debian's Python (/usr/bin/python3):
#
#   bash scripts/install_python.sh           into /usr/local/lib/python3.X/dist-packages (as root)
#   bash scripts/install_python.sh --user    into the user's site-packages (~/.local/lib/python3.X/...)
#
# Installs what it needs first (apt: the build dependencies, pybind11-dev, python3-dev,
# python3-numpy), configures build/ (shared with scripts/build.sh), builds the target `_prstar` only,
# and installs the component `python`.  Then checks that `import prstar` works from another folder.
set -euo pipefail
cd "$(dirname "$0")/.."
user=false
case "${1:-}" in
  --user) user=true ;;
  "") ;;
  *) echo "install_python.sh: unknown option $1 (--user, or nothing for the system's site-packages)" >&2; exit 2 ;;
esac
bash scripts/install_dependencies.sh --python
python=/usr/bin/python3
mkdir -p build
args=(-DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=$python)
if $user; then
  args+=("-DPRSTAR_PYTHON_INSTALL_DIR=$($python -m site --user-site)")
else
  args+=("-DPRSTAR_PYTHON_INSTALL_DIR=$($python -c "import sysconfig; print(sysconfig.get_path('platlib'))")")
fi
cmake -S . -B build "${args[@]}" > build/configure.log 2>&1 || { cat build/configure.log; exit 1; }
grep "Python module" build/configure.log
cmake --build build -j "${JOBS:-2}" --target _prstar
cmake --install build --component python
cd /
$python -c "import prstar; print('prstar', prstar.__version__, 'installed in', prstar.__path__[0])"
