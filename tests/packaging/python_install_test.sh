#!/usr/bin/env bash
# ctest packaging.python_install: cmake --install under a scratch prefix puts the Python module in
# <prefix>/lib/python3.X/dist-packages (what Debian's python3 reads under /usr/local), and the
# installed module runs from elsewhere with the installed libraries and data (docs/python.md).
#   python_install_test.sh BUILD_DIR
set -euo pipefail
build=$1
tmp=$(mktemp -d /tmp/gc_python_install.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
version=$(/usr/bin/python3 -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')
site=$prefix/lib/python$version/dist-packages
[ -f "$site/gearcoupling/__init__.py" ] || fail "no module in $site"
# /usr/local's folder is on Debian's python3 path: the same layout under /usr/local is found.
/usr/bin/python3 -c 'import sys; assert "/usr/local/lib/python'"$version"'/dist-packages" in sys.path, sys.path' ||
  fail "Debian's python3 does not read /usr/local/lib/python$version/dist-packages"
cd "$tmp"
unset GEARCOUPLING_CATALOG GEARCOUPLING_MODELS
PYTHONPATH=$site /usr/bin/python3 - "$prefix" <<'PY' || fail "the installed module does not run"
import sys
import gearcoupling as gc
prefix = sys.argv[1]
assert gc.__file__.startswith(prefix), gc.__file__
assert str(gc.bundled_data_dir("models")) == prefix + "/share/gearcoupling/models"
result = gc.induced_moments_many("nrel_upwind", [1e6, 1.5e6], 0.005, mu=0.1)
print("installed module:", result["magnitude_nm"])
PY
echo "PASS: the installed Python module runs"
